#include "contexts/gl/program.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <sstream>

#include "contexts/gl/shader_sources.h"
#include "core/util/error.h"

namespace sandstorm::gl {
namespace {

GLenum stageOf(std::string_view file) {
  const auto ends = [&](std::string_view ext) { return file.ends_with(ext); };
  if (ends(".vert")) return GL_VERTEX_SHADER;
  if (ends(".geom")) return GL_GEOMETRY_SHADER;
  if (ends(".frag")) return GL_FRAGMENT_SHADER;
  if (ends(".comp")) return GL_COMPUTE_SHADER;
  throw Error(concat("gl::Program: cannot tell the stage of '", file,
                     "'; expected .vert, .geom, .frag or .comp"));
}

void expand(std::string_view name, std::vector<std::string>& files, std::ostringstream& out,
            int depth) {
  if (depth > 8) throw Error(concat("gl::Program: includes nested too deeply at '", name, "'"));
  const int index = int(files.size());
  files.emplace_back(name);
  std::istringstream in{std::string(shaderSource(name))};
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::size_t at = line.find("#include");
    if (at != std::string::npos && line.find_first_not_of(" \t") == at &&
        line.find('<', at) != std::string::npos) {
      // A C header a library's shared GLSL/C file includes on its C side only
      // (PNanoVDB.h): inside an #if that GLSL never takes.
      out << "// " << line << " (C only)\n";
      continue;
    }
    if (at != std::string::npos && line.find_first_not_of(" \t") == at) {
      const std::size_t open = line.find('"'), close = line.rfind('"');
      if (open == std::string::npos || close <= open)
        throw Error(concat(name, ":", lineNo, ": expected #include \"file.glsl\""));
      out << "#line 1 " << files.size() << "\n";
      expand(line.substr(open + 1, close - open - 1), files, out, depth + 1);
      out << "#line " << lineNo + 1 << " " << index << "\n";
      continue;
    }
    out << line << "\n";
  }
}

std::string fileMap(const std::vector<std::string>& files) {
  std::string s;
  for (std::size_t i = 0; i < files.size(); ++i)
    s += concat("  source ", i, " = ", files[i], "\n");
  return s;
}

}  // namespace

std::string preprocessShader(std::string_view fileName, const std::vector<std::string>& defines,
                             std::vector<std::string>& files) {
  std::ostringstream body;
  expand(fileName, files, body, 0);
  std::string text = body.str();
  // #version must come first; defines follow it, then the rest at its own line numbers.
  const std::size_t version = text.find("#version");
  if (version == std::string::npos)
    throw Error(concat("gl::Program: ", fileName, " has no #version line"));
  const std::size_t eol = text.find('\n', version);
  std::string header = text.substr(0, eol + 1);
  for (const std::string& d : defines)
    header += "#define " + d + "\n";
  const int versionLine = int(std::count(text.begin(), text.begin() + long(eol), '\n')) + 1;
  header += concat("#line ", versionLine + 1, " 0\n");
  return header + text.substr(eol + 1);
}

Program::Program(const ProgramDesc& desc) {
  for (const std::string& f : desc.files)
    name_ += (name_.empty() ? "" : "+") + f;
  program_ = ProgramObject::wrap(glCreateProgram());
  std::vector<ShaderObject> shaders;
  for (const std::string& file : desc.files) {
    std::vector<std::string> files;
    const std::string source = preprocessShader(file, desc.defines, files);
    ShaderObject shader = ShaderObject::wrap(glCreateShader(stageOf(file)));
    const char* text = source.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = 0, length = 0;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
      std::string log(std::size_t(std::max(length, 1)), '\0');
      glGetShaderInfoLog(shader.id(), length, nullptr, log.data());
      throw Error(concat("gl::Program: compiling shaders/", file, " failed with:\n", log.c_str(),
                         "\n(GLSL source numbers:\n", fileMap(files), ")"));
    }
    glAttachShader(program_.id(), shader.id());
    shaders.push_back(std::move(shader));
  }
  if (!desc.feedbackVaryings.empty()) {
    std::vector<const char*> names;
    for (const std::string& v : desc.feedbackVaryings)
      names.push_back(v.c_str());
    glTransformFeedbackVaryings(program_.id(), GLsizei(names.size()), names.data(),
                                GL_SEPARATE_ATTRIBS);
  }
  glLinkProgram(program_.id());
  GLint ok = 0, length = 0;
  glGetProgramiv(program_.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    glGetProgramiv(program_.id(), GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program_.id(), length, nullptr, log.data());
    throw Error(concat("gl::Program: linking ", name_, " failed with:\n", log.c_str()));
  }
  for (const ShaderObject& s : shaders)
    glDetachShader(program_.id(), s.id());
}

void Program::use() const {
  glUseProgram(program_.id());
}

int Program::uniform(std::string_view name) const {
  const auto it = locations_.find(name);
  if (it != locations_.end()) return it->second;
  const int location = glGetUniformLocation(program_.id(), std::string(name).c_str());
  locations_.emplace(std::string(name), location);
  return location;
}

}  // namespace sandstorm::gl

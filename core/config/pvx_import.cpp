#include "core/config/pvx_import.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "core/util/error.h"

namespace sandstorm {
namespace {

// The attributes of one XML start tag, `<Machine a="1" b="2" ... />`.
std::map<std::string, std::string> attributes(const std::string& tag, const std::string& where) {
  std::map<std::string, std::string> out;
  std::size_t i = tag.find_first_of(" \t\r\n");
  while (i != std::string::npos && i < tag.size()) {
    const std::size_t nameStart = tag.find_first_not_of(" \t\r\n/>", i);
    if (nameStart == std::string::npos) break;
    const std::size_t eq = tag.find('=', nameStart);
    if (eq == std::string::npos) break;
    std::string name = tag.substr(nameStart, eq - nameStart);
    while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back())))
      name.pop_back();
    const std::size_t open = tag.find_first_of("\"'", eq);
    if (open == std::string::npos)
      throw Error(where + ": attribute " + name + " has no quoted value");
    const std::size_t close = tag.find(tag[open], open + 1);
    if (close == std::string::npos)
      throw Error(where + ": attribute " + name + "'s value is not closed");
    out[name] = tag.substr(open + 1, close - open - 1);
    i = close + 1;
  }
  return out;
}

glm::vec3 corner(const std::map<std::string, std::string>& a, const std::string& key,
                 const std::string& where, bool yUp) {
  const auto it = a.find(key);
  if (it == a.end()) throw Error(where + ": missing " + key + " (expected three numbers)");
  std::istringstream in(it->second);
  glm::vec3 v;
  std::string extra;
  if (!(in >> v.x >> v.y >> v.z) || (in >> extra))
    throw Error(where + ": " + key + "=\"" + it->second + "\"; expected three numbers");
  return yUp ? glm::vec3(v.x, -v.z, v.y) : v;
}

}  // namespace

std::vector<WallSpec> parsePvx(const std::string& text, const std::string& name, bool yUp) {
  std::vector<WallSpec> walls;
  std::size_t at = 0;
  while ((at = text.find("<Machine", at)) != std::string::npos) {
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos) throw Error(name + ": a <Machine> tag is not closed");
    const int line = int(std::count(text.begin(), text.begin() + long(at), '\n')) + 1;
    const std::string tag = text.substr(at, end - at + 1);
    const auto a = attributes(tag, concat(name, ":", line));
    WallSpec w;
    w.line = line;
    w.rank = int(walls.size());  // as ParaView does: machine i is rank i (cluster mode)
    w.name = a.count("Name") ? a.at("Name") : concat("machine", walls.size());
    const std::string where = concat(name, ":", line, ": machine '", w.name, "'");
    w.corners.lowerLeft = corner(a, "LowerLeft", where, yUp);
    w.corners.lowerRight = corner(a, "LowerRight", where, yUp);
    const glm::vec3 upperRight = corner(a, "UpperRight", where, yUp);
    w.corners.upperLeft = w.corners.lowerLeft + (upperRight - w.corners.lowerRight);
    validateWall(w.corners, where);
    if (const auto g = a.find("Geometry"); g != a.end()) {
      WindowSpec s;
      char x = 0, p1 = 0, p2 = 0;
      std::istringstream in(g->second);
      if (!(in >> s.size.x >> x >> s.size.y) || x != 'x' || s.size.x < 16 || s.size.y < 16)
        throw Error(where + ": Geometry=\"" + g->second + "\"; expected WIDTHxHEIGHT+X+Y");
      if (in >> p1 >> s.position.x >> p2 >> s.position.y) {
        if (p1 != '+' || p2 != '+')
          throw Error(where + ": Geometry=\"" + g->second + "\"; expected WIDTHxHEIGHT+X+Y");
      }
      s.fullscreen = a.count("FullScreen") && a.at("FullScreen") == "1";
      s.decorated = !s.fullscreen;
      w.window = s;
      w.offscreenSize = s.size;
    }
    walls.push_back(w);
    at = end;
  }
  if (walls.empty())
    throw Error(name + ": no <Machine> with screen corners; is this a ParaView .pvx file?");
  return walls;
}

std::vector<WallSpec> readPvx(const std::filesystem::path& path, bool yUp) {
  std::ifstream in(path);
  if (!in) throw Error(concat(path.string(), ": cannot open the .pvx file"));
  std::ostringstream text;
  text << in.rdbuf();
  return parsePvx(text.str(), path.string(), yUp);
}

}  // namespace sandstorm

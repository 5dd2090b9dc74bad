#include "core/io/field_stream_scanner.h"

#include <algorithm>
#include <fstream>
#include <set>

#include "core/io/field_format.h"
#include "core/io/pvd_file.h"
#include "core/util/error.h"

namespace sandstorm {
namespace {

namespace fs = std::filesystem;

// A step of a folder: a field file, not hidden, not a collection of steps itself.
bool fieldFile(const fs::path& p) {
  const std::string name = p.filename().string();
  if (name.empty() || name.front() == '.') return false;
  const FieldFormat format = formatForExtension(p);
  return format != FieldFormat::Unknown && format != FieldFormat::VtkCollection;
}

// Whether an XML file ends with its root's closing tag (a .pvd caught half
// written does not; VTK's parser would print an error for it on every look).
bool wholeXml(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff tail = std::min<std::streamoff>(size, 256);
  std::string end(std::size_t(tail), '\0');
  in.seekg(size - tail);
  in.read(end.data(), tail);
  const std::size_t last = end.find_last_not_of(" \t\r\n");
  return last != std::string::npos && end.substr(0, last + 1).ends_with("</VTKFile>");
}

}  // namespace

FieldStreamScanner::FieldStreamScanner(fs::path source, double interval, int patience,
                                       double settle)
    : source_(std::move(source)),
      interval_(interval),
      patience_(std::max(patience, 1)),
      settle_(std::max(settle, 0.0)) {
  std::error_code ec;
  folder_ = fs::is_directory(source_, ec);
  if (!folder_ && source_.extension() != ".pvd")
    throw Error(concat("field source ", source_.string(),
                       ": expected a folder or a .pvd collection to watch"));
  if (!(interval_ > 0.0))
    throw Error(concat("field source ", source_.string(), ": the steps' interval must be > 0 s"));
}

bool FieldStreamScanner::settled(const fs::path& file) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec) {
    seen_.erase(file);
    return false;
  }
  const fs::file_time_type written = fs::last_write_time(file, ec);
  if (ec) {
    seen_.erase(file);
    return false;
  }
  const auto now = std::chrono::steady_clock::now();
  Seen& s = seen_[file];
  if (s.looks > 0 && s.size == size && s.written == written)
    ++s.looks;
  else
    s = Seen{size, written, 1, now};
  return size > 0 && s.looks >= 2 &&
         std::chrono::duration<double>(now - s.since).count() >= settle_;
}

std::vector<FieldStreamScanner::Step> FieldStreamScanner::poll(std::vector<std::string>& messages) {
  std::vector<Step> out = std::move(back_);
  back_.clear();
  for (Step& s : folder_ ? pollFolder(messages) : pollPvd(messages))
    out.push_back(std::move(s));
  return out;
}

void FieldStreamScanner::putBack(std::vector<Step> steps) {
  back_.insert(back_.begin(), steps.begin(), steps.end());
}

std::vector<FieldStreamScanner::Step> FieldStreamScanner::pollFolder(
    std::vector<std::string>& messages) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (auto it = fs::directory_iterator(source_, ec); !ec && it != fs::directory_iterator();
       it.increment(ec))
    if (it->is_regular_file(ec) && fieldFile(it->path())) files.push_back(it->path());
  // A simulation on many ranks writes each step as an index (.pvtu, .vtm)
  // beside its pieces: then the indexes are the steps.
  if (std::any_of(files.begin(), files.end(),
                  [](const fs::path& f) { return namesOtherFiles(formatForExtension(f)); }))
    std::erase_if(files, [](const fs::path& f) { return !namesOtherFiles(formatForExtension(f)); });
  std::sort(files.begin(), files.end());
  // Every candidate is looked at (each needs two looks); steps come in order,
  // so the first one not yet complete holds back those after it.
  std::vector<Step> out;
  bool waiting = false;
  for (const fs::path& file : files) {
    if (newestFile_ && !(*newestFile_ < file)) {
      if (file != *newestFile_ && seen_.count(file) == 0) {
        messages.push_back(concat(file.string(), ": skipped: it appeared after the later step ",
                                  newestFile_->filename().string(),
                                  " (steps are taken in name order)"));
        seen_[file] = Seen{0, {}, -1};  // said once
      }
      continue;
    }
    if (!settled(file) || waiting) {
      waiting = true;
      continue;
    }
    out.push_back({double(folderSteps_++) * interval_, file});
    newestFile_ = file;
  }
  // Forget files that went away before they settled.
  for (auto it = seen_.begin(); it != seen_.end();)
    it = fs::exists(it->first, ec) || it->second.looks < 0 ? std::next(it) : seen_.erase(it);
  return out;
}

std::vector<FieldStreamScanner::Step> FieldStreamScanner::pollPvd(
    std::vector<std::string>& messages) {
  std::error_code ec;
  if (!fs::exists(source_, ec)) return {};  // not there (yet)
  if (!wholeXml(source_)) return {};        // being rewritten: look again next time
  std::vector<PvdFrame> frames;
  try {
    frames = readPvd(source_);
  } catch (const Error&) {
    return {};  // being rewritten: look again next time
  }
  std::vector<Step> out;
  for (const PvdFrame& f : frames) {
    if (newestTime_ && !(f.time > *newestTime_)) continue;
    if (f.parts.size() > 1) {
      // Never one part shown as if it were the whole step.
      messages.push_back(concat(source_.string(), ": the step at t = ", f.time, " s has ",
                                f.parts.size(),
                                " parts; a watched .pvd follows one file a step: skipped (without "
                                "field.watch its parts are read together)"));
      newestTime_ = f.time;
      continue;
    }
    if (!fs::exists(f.file(), ec)) {
      if (++missing_[f.file()] < patience_) break;  // wait for it, in order
      messages.push_back(concat(source_.string(), ": the step at t = ", f.time, " s (",
                                f.file().string(), ") stayed missing for ", patience_,
                                " looks: skipped"));
      missing_.erase(f.file());
      newestTime_ = f.time;
      continue;
    }
    missing_.erase(f.file());
    if (!settled(f.file())) break;
    out.push_back({f.time, f.file()});
    newestTime_ = f.time;
  }
  return out;
}

}  // namespace sandstorm

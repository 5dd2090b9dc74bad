#include "app/menu/menu_script.h"

#include <fstream>
#include <sstream>

#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {

MenuScript MenuScript::parse(const std::string& text, const std::string& name) {
  MenuScript script;
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    std::istringstream words(line);
    std::string first;
    if (!(words >> first) || first.starts_with("#")) continue;
    Click c;
    std::string action;
    try {
      c.frame = std::uint32_t(std::stoul(first));
    } catch (...) {
      throw Error(concat(name, ":", lineNo, ": expected a frame number, got '", first, "'"));
    }
    if (!(words >> action) || (action != "click" && action != "close") ||
        (action == "click" && !(words >> c.widget)))
      throw Error(
          concat(name, ":", lineNo, ": expected 'FRAME click WIDGET [FRACTION]' or 'FRAME close'"));
    if (action == "close") {
      script.clicks_.push_back(c);
      continue;
    }
    if (std::string f; words >> f) {
      try {
        c.across = std::stof(f);
      } catch (...) {
        c.across = -1.0f;
      }
      if (!(c.across >= 0.0f && c.across <= 1.0f))
        throw Error(concat(name, ":", lineNo,
                           ": the fraction across the widget must be in 0..1, got '", f, "'"));
    }
    script.clicks_.push_back(c);
  }
  return script;
}

MenuScript MenuScript::load(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw Error(concat(path.string(), ": cannot open the menu script"));
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str(), path.string());
}

bool MenuScript::closesBy(std::uint32_t frame) const {
  for (const Click& c : clicks_)
    if (c.widget.empty() && frame >= c.frame) return true;
  return false;
}

void MenuScript::inject(std::uint32_t frame, ImGuiSession& session, const MenuPanel& panel) const {
  for (const Click& c : clicks_) {
    if (c.widget.empty() || frame < c.frame || frame > c.frame + 2) continue;
    const auto it = panel.rects().find(c.widget);
    if (it == panel.rects().end()) {
      if (frame == c.frame)
        log::warn("menu script: no widget '", c.widget, "' on the panel at frame ", frame);
      continue;
    }
    const MenuPanel::Rect& r = it->second;
    const glm::vec2 at(r.min.x + c.across * (r.max.x - r.min.x), 0.5f * (r.min.y + r.max.y));
    session.injectMouse(at, frame == c.frame + 1);  // hover, press, release
    log::debug("menu script: frame ", frame, ": mouse at ", at.x, ",", at.y,
               frame == c.frame + 1 ? " down" : " up", " on ", c.widget);
  }
}

}  // namespace sandstorm

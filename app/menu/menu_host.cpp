#include "app/menu/menu_host.h"

namespace sandstorm {

MenuHost::MenuHost(MainContext& main, std::unique_ptr<GlfwWindow> operatorWindow,
                   GLFWwindow* wallWindow, glm::ivec2 wallSize, StereoMode wallStereo,
                   std::vector<std::string> fieldChoices, MenuPanel::FieldLoader loader,
                   MenuPanel::FieldWriter writer, std::optional<MenuScript> script)
    : operatorWindow_(std::move(operatorWindow)),
      session_(operatorWindow_ ? operatorWindow_->handle() : wallWindow, wallSize,
               operatorWindow_ ? StereoMode::Mono : wallStereo),
      panel_(main, std::move(fieldChoices), std::move(loader), std::move(writer)),
      script_(std::move(script)) {
  if (operatorWindow_) {
    operatorWindow_->makeCurrent();
    renderer_ = std::make_unique<UiRenderer>(session_.font());
    operatorWindow_->releaseCurrent();
  }
}

MenuHost::~MenuHost() {
  if (operatorWindow_) {
    operatorWindow_->makeCurrent();
    renderer_.reset();  // its GL objects go with their own context current
    operatorWindow_->releaseCurrent();
  }
}

void MenuHost::pointWand(glm::vec2 pixel, bool down) {
  wand_ = std::make_pair(pixel, down);
}

void MenuHost::frame(std::uint32_t frame, float dt, const MenuStats& stats) {
  if (wand_) {
    session_.injectMouse(wand_->first, wand_->second);
  } else if (wandPointed_) {
    session_.injectMouse(glm::vec2(-1e9f),
                         false);  // the wand left the panel: let go, hover nothing
  }
  session_.drawCursor(wand_.has_value());  // where on the panel the ray is
  wandPointed_ = wand_.has_value();
  wand_.reset();
  if (script_) script_->inject(frame, session_, panel_);
  session_.begin(dt);
  panel_.build(stats);
  std::shared_ptr<const UiDrawData> data = session_.end();
  if (operatorWindow_) {
    operatorWindow_->makeCurrent();
    renderer_->drawWindow(*data, operatorWindow_->framebufferSize());
    operatorWindow_->swapBuffers();
    operatorWindow_->releaseCurrent();
  }
  std::lock_guard lock(mutex_);
  latest_ = std::move(data);
}

std::shared_ptr<const UiDrawData> MenuHost::latest() const {
  std::lock_guard lock(mutex_);
  return operatorWindow_ ? nullptr : latest_;
}

bool MenuHost::operatorWindowClosed() const {
  return operatorWindow_ && operatorWindow_->shouldClose();
}

}  // namespace sandstorm

#include "app/menu/imgui_session.h"

#include <imgui.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>

#include <cfloat>
#include <cstring>

#include "core/cave/wall_views.h"

namespace sandstorm {

static_assert(sizeof(ImDrawIdx) == 2, "UiDrawData carries 16-bit indices");
static_assert(sizeof(ImDrawVert) == sizeof(UiVertex), "UiVertex mirrors ImDrawVert");

ImGuiSession::ImGuiSession(GLFWwindow* window, glm::ivec2 size, StereoMode eyes)
    : window_(window), size_(size), eyes_(eyes) {
  IMGUI_CHECKVERSION();
  // Another session's context (the menu's) stays current between frames: its
  // GLFW callbacks use whichever context is current when events arrive.
  ImGuiContext* const previous = ImGui::GetCurrentContext();
  context_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini litter; the layout is fixed
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 4.0f;
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  font_ =
      UiFont{w, h, std::vector<std::uint8_t>(pixels, pixels + std::size_t(w) * std::size_t(h) * 4)};
  io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(std::intptr_t(1)));
  if (window_) ImGui_ImplGlfw_InitForOther(window_, true);
  if (previous) ImGui::SetCurrentContext(previous);
}

ImGuiSession::~ImGuiSession() {
  ImGuiContext* const previous = ImGui::GetCurrentContext();
  ImGui::SetCurrentContext(context_);
  if (window_) ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext(context_);
  if (previous && previous != context_) ImGui::SetCurrentContext(previous);
}

void ImGuiSession::begin(float dt) {
  previous_ = ImGui::GetCurrentContext();
  ImGui::SetCurrentContext(context_);
  ImGuiIO& io = ImGui::GetIO();
  if (window_) {
    ImGui_ImplGlfw_NewFrame();  // the window's size, and its mouse polled (imgui 1.86)
    const glm::vec2 window(io.DisplaySize.x, io.DisplaySize.y);
    const glm::vec2 eye = eyeImageSize(eyes_, window);
    io.DisplaySize = ImVec2(eye.x, eye.y);
    if (io.MousePos.x > -FLT_MAX && io.MousePos.y > -FLT_MAX) {  // not "no mouse"
      const glm::vec2 at = pointInEyeImage(eyes_, window, {io.MousePos.x, io.MousePos.y});
      io.MousePos = ImVec2(at.x, at.y);
    }
  } else {
    const glm::vec2 eye = eyeImageSize(eyes_, glm::vec2(size_));
    io.DisplaySize = ImVec2(eye.x, eye.y);
  }
  io.DeltaTime = dt > 0.0f ? dt : 1.0f / 60.0f;
  if (injected_) {
    io.MousePos = ImVec2(mouse_.x, mouse_.y);
    io.MouseDown[0] = mouseDown_;
    injected_ = false;
  }
  ImGui::NewFrame();
}

std::shared_ptr<const UiDrawData> ImGuiSession::end() {
  ImGui::SetCurrentContext(context_);
  ImGui::Render();
  const ImDrawData* dd = ImGui::GetDrawData();
  auto out = std::make_shared<UiDrawData>();
  out->displayPos = {dd->DisplayPos.x, dd->DisplayPos.y};
  out->displaySize = {dd->DisplaySize.x, dd->DisplaySize.y};
  out->framebufferScale = {dd->FramebufferScale.x, dd->FramebufferScale.y};
  for (int l = 0; l < dd->CmdListsCount; ++l) {
    const ImDrawList* list = dd->CmdLists[l];
    const std::size_t vertexBase = out->vertices.size(), indexBase = out->indices.size();
    out->vertices.resize(vertexBase + std::size_t(list->VtxBuffer.Size));
    std::memcpy(out->vertices.data() + vertexBase, list->VtxBuffer.Data,
                std::size_t(list->VtxBuffer.Size) * sizeof(UiVertex));
    out->indices.insert(out->indices.end(), list->IdxBuffer.Data,
                        list->IdxBuffer.Data + list->IdxBuffer.Size);
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      if (cmd.UserCallback) continue;
      out->commands.push_back(
          UiCommand{{cmd.ClipRect.x, cmd.ClipRect.y, cmd.ClipRect.z, cmd.ClipRect.w},
                    cmd.ElemCount,
                    std::uint32_t(indexBase + cmd.IdxOffset),
                    std::int32_t(vertexBase + cmd.VtxOffset)});
    }
  }
  if (previous_ && previous_ != context_) ImGui::SetCurrentContext(previous_);
  return out;
}

void ImGuiSession::injectMouse(glm::vec2 position, bool down) {
  injected_ = true;
  mouse_ = position;
  mouseDown_ = down;
}

void ImGuiSession::drawCursor(bool on) {
  ImGui::SetCurrentContext(context_);
  ImGui::GetIO().MouseDrawCursor = on;
}

bool ImGuiSession::wantsMouse() const {
  ImGui::SetCurrentContext(context_);
  return ImGui::GetIO().WantCaptureMouse;
}

bool ImGuiSession::wantsKeyboard() const {
  ImGui::SetCurrentContext(context_);
  return ImGui::GetIO().WantCaptureKeyboard;
}

}  // namespace sandstorm

#include "play/ui_layer.hpp"

#include <array>
#include <filesystem>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include "render/context.hpp"
#include "render/vulkan_error.hpp"

namespace play {
namespace {

// A clear sans-serif where Debian has one (fonts-dejavu-core); ImGui's built-in bitmap font,
// which blurs when scaled, otherwise.
constexpr const char* kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr float kFontPixels = 17.0f;

void checkImguiResult(VkResult result) {
  render::vkCheck(result, "Dear ImGui's Vulkan backend");
}

}  // namespace

UiLayer::UiLayer(const render::Context& context, GLFWwindow* window,
                 const render::Presenter& presenter, float uiScale)
    : context_(context) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the player's working directory
  io.LogFilename = nullptr;
  io.ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard | ImGuiConfigFlags_NavEnableGamepad;
  ImGui::StyleColorsDark();
  ImGui::GetStyle().ScaleAllSizes(uiScale);
  std::error_code error;
  if (std::filesystem::exists(kFontFile, error))
    io.Fonts->AddFontFromFileTTF(kFontFile, kFontPixels * uiScale);
  else
    io.Fonts->AddFontDefault();

  try {
    const std::array<VkDescriptorPoolSize, 1> sizes = {
        VkDescriptorPoolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4}};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = 4;
    poolInfo.poolSizeCount = uint32_t(sizes.size());
    poolInfo.pPoolSizes = sizes.data();
    render::vkCheck(vkCreateDescriptorPool(context.device(), &poolInfo, nullptr, &descriptorPool_),
                    "vkCreateDescriptorPool");

    glfwBackend_ = ImGui_ImplGlfw_InitForVulkan(window, true);
    if (!glfwBackend_) throw render::RenderError("Dear ImGui's GLFW backend did not start");
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context.instance();
    info.PhysicalDevice = context.physicalDevice();
    info.Device = context.device();
    info.QueueFamily = context.queueFamily();
    info.Queue = context.queue();
    info.DescriptorPool = descriptorPool_;
    info.Subpass = 0;
    info.MinImageCount = presenter.minImageCount();
    info.ImageCount = std::max(presenter.imageCount(), presenter.minImageCount());
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkImguiResult;
    vulkanBackend_ = ImGui_ImplVulkan_Init(&info, presenter.renderPass());
    if (!vulkanBackend_) throw render::RenderError("Dear ImGui's Vulkan backend did not start");
    context.submitAndWait(
        [](VkCommandBuffer commands) { ImGui_ImplVulkan_CreateFontsTexture(commands); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
  } catch (...) {
    release();
    throw;
  }
}

UiLayer::~UiLayer() {
  release();
}

void UiLayer::release() {
  if (!ImGui::GetCurrentContext()) return;
  vkDeviceWaitIdle(context_.device());  // the last overlay may still be drawing
  if (vulkanBackend_) ImGui_ImplVulkan_Shutdown();
  if (glfwBackend_) ImGui_ImplGlfw_Shutdown();
  vulkanBackend_ = glfwBackend_ = false;
  if (descriptorPool_) vkDestroyDescriptorPool(context_.device(), descriptorPool_, nullptr);
  descriptorPool_ = VK_NULL_HANDLE;
  ImGui::DestroyContext();
}

void UiLayer::beginFrame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

render::OverlayDraw UiLayer::endFrame() {
  ImGui::Render();
  ImDrawData* drawData = ImGui::GetDrawData();
  if (!drawData || drawData->CmdListsCount == 0) return {};
  return
      [drawData](VkCommandBuffer commands) { ImGui_ImplVulkan_RenderDrawData(drawData, commands); };
}

}  // namespace play

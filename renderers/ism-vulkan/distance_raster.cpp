#include "distance_raster.hpp"

#include "compute_kernel.hpp"

#include <array>
#include <cstring>

namespace hilight::ism {

namespace {

constexpr VkFormat kDistanceFormat = VK_FORMAT_R32_SFLOAT;
constexpr VkFormat kTriangleFormat = VK_FORMAT_R32_UINT;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

struct ViewConstants {
  float view_projection[16];  // column-major, as GLSL reads a mat4
  float eye[4];
};

/// clip = M·(p, 1): x = (p−e)·right, y = (p−e)·up, w = (p−e)·forward, and z
/// maps [near, far] of w to depth [0, 1].
ViewConstants view_constants(const RasterView& v) {
  const float a = v.far_plane / (v.far_plane - v.near_plane), b = -v.far_plane * v.near_plane / (v.far_plane - v.near_plane);
  const Vec3 rows[4] = {v.right, v.up, v.forward * a, v.forward};
  const float offsets[4] = {-glm::dot(v.right, v.eye), -glm::dot(v.up, v.eye), -a * glm::dot(v.forward, v.eye) + b,
                            -glm::dot(v.forward, v.eye)};
  ViewConstants c{};
  for (int r = 0; r < 4; ++r) {
    for (int col = 0; col < 3; ++col) c.view_projection[col * 4 + r] = rows[r][col];
    c.view_projection[12 + r] = offsets[r];
  }
  c.eye[0] = v.eye.x;
  c.eye[1] = v.eye.y;
  c.eye[2] = v.eye.z;
  return c;
}

VkRenderPass create_pass(VkDevice device) {
  std::array<VkAttachmentDescription, 3> attachments{};
  const VkFormat formats[3] = {kDistanceFormat, kTriangleFormat, kDepthFormat};
  for (int k = 0; k < 3; ++k) {
    attachments[k].format = formats[k];
    attachments[k].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[k].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[k].storeOp = k < 2 ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[k].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[k].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[k].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[k].finalLayout = k < 2 ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  }
  VkAttachmentReference colours[2] = {{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}, {1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}};
  VkAttachmentReference depth{2, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 2;
  subpass.pColorAttachments = colours;
  subpass.pDepthStencilAttachment = &depth;
  // Passes run back to back on one depth image, and the copies read the colours.
  std::array<VkSubpassDependency, 2> dependencies{};
  dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[0].dstSubpass = 0;
  dependencies[0].srcStageMask = VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                 VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[0].srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT;
  dependencies[0].dstStageMask = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[0].dstAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                  VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = uint32_t(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = uint32_t(dependencies.size());
  info.pDependencies = dependencies.data();
  VkRenderPass pass = VK_NULL_HANDLE;
  check(vkCreateRenderPass(device, &info, nullptr, &pass), "vkCreateRenderPass");
  return pass;
}

} // namespace

std::vector<RasterView> cube_views(const Vec3& eye, float near_plane, float far_plane) {
  static const Vec3 forward[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  static const Vec3 right[6] = {{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {-1, 0, 0}};
  static const Vec3 up[6] = {{0, 1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}, {0, 1, 0}, {0, 1, 0}};
  std::vector<RasterView> views;
  for (int f = 0; f < 6; ++f) views.push_back({eye, forward[f], right[f], up[f], near_plane, far_plane});
  return views;
}

DistanceRaster::DistanceRaster(VulkanContext& context, const Buffer& vertices, const Buffer& indices, uint32_t triangle_count,
                               std::span<const uint32_t> vertex_spirv, std::span<const uint32_t> fragment_spirv)
    : m_context(context), m_vertices(vertices), m_indices(indices), m_triangles(triangle_count) {
  VkDevice device = context.device();
  try {
    m_pass = create_pass(device);
    m_vertex = create_shader_module(context, vertex_spirv);
    m_fragment = create_shader_module(context, fragment_spirv);
    VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(ViewConstants)};
    VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout.pushConstantRangeCount = 1;
    layout.pPushConstantRanges = &range;
    check(vkCreatePipelineLayout(device, &layout, nullptr, &m_layout), "vkCreatePipelineLayout");

    VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                                 {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = m_vertex;
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = m_fragment;
    stages[1].pName = "main";
    VkVertexInputBindingDescription binding{0, 3 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription attribute{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
    VkPipelineVertexInputStateCreateInfo input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    input.vertexBindingDescriptionCount = 1;
    input.pVertexBindingDescriptions = &binding;
    input.vertexAttributeDescriptionCount = 1;
    input.pVertexAttributeDescriptions = &attribute;
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = VK_CULL_MODE_NONE;  // two-sided surfaces
    raster.lineWidth = 1.f;
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = VK_TRUE;
    depth.depthWriteEnable = VK_TRUE;
    depth.depthCompareOp = VK_COMPARE_OP_LESS;
    VkPipelineColorBlendAttachmentState blend[2]{};
    blend[0].colorWriteMask = blend[1].colorWriteMask = VK_COLOR_COMPONENT_R_BIT;
    VkPipelineColorBlendStateCreateInfo blending{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blending.attachmentCount = 2;
    blending.pAttachments = blend;
    VkDynamicState dynamic_states[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = 2;
    dynamic.pDynamicStates = dynamic_states;
    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.stageCount = 2;
    info.pStages = stages;
    info.pVertexInputState = &input;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blending;
    info.pDynamicState = &dynamic;
    info.layout = m_layout;
    info.renderPass = m_pass;
    check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &m_pipeline), "vkCreateGraphicsPipelines");
  } catch (...) {
    release();
    throw;
  }
}

DistanceRaster::~DistanceRaster() { release(); }

void DistanceRaster::release() {
  VkDevice device = m_context.device();
  release_targets();
  if (m_pipeline) vkDestroyPipeline(device, m_pipeline, nullptr);
  if (m_layout) vkDestroyPipelineLayout(device, m_layout, nullptr);
  if (m_vertex) vkDestroyShaderModule(device, m_vertex, nullptr);
  if (m_fragment) vkDestroyShaderModule(device, m_fragment, nullptr);
  if (m_pass) vkDestroyRenderPass(device, m_pass, nullptr);
  m_pipeline = VK_NULL_HANDLE;
  m_layout = VK_NULL_HANDLE;
  m_vertex = m_fragment = VK_NULL_HANDLE;
  m_pass = VK_NULL_HANDLE;
}

void DistanceRaster::release_targets() {
  for (auto fb : m_framebuffers) vkDestroyFramebuffer(m_context.device(), fb, nullptr);
  m_framebuffers.clear();
  m_distance.reset();
  m_triangle.reset();
  m_depth.reset();
}

void DistanceRaster::make_targets(uint32_t width, uint32_t height, uint32_t layers) {
  if (m_distance.handle() && m_distance.width() == width && m_distance.height() == height && m_distance.layers() == layers) return;
  release_targets();
  const VkImageUsageFlags colour = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  m_distance = DeviceImage(m_context, kDistanceFormat, colour, VK_IMAGE_ASPECT_COLOR_BIT, width, height, layers, "shadow/distance maps");
  m_triangle = DeviceImage(m_context, kTriangleFormat, colour, VK_IMAGE_ASPECT_COLOR_BIT, width, height, layers, "triangle maps");
  m_depth = DeviceImage(m_context, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT, width, height, 1,
                  "depth buffer");
  for (uint32_t layer = 0; layer < layers; ++layer) {
    VkImageView views[3] = {m_distance.layer_view(layer), m_triangle.layer_view(layer), m_depth.layer_view(0)};
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = m_pass;
    info.attachmentCount = 3;
    info.pAttachments = views;
    info.width = width;
    info.height = height;
    info.layers = 1;
    VkFramebuffer fb = VK_NULL_HANDLE;
    check(vkCreateFramebuffer(m_context.device(), &info, nullptr, &fb), "vkCreateFramebuffer");
    m_framebuffers.push_back(fb);
  }
}

void DistanceRaster::record(VkCommandBuffer cmd, std::span<const RasterView> views, uint32_t width, uint32_t height,
                            const Buffer& distances, const Buffer& triangles) {
  const uint32_t layers = uint32_t(views.size());
  make_targets(width, height, layers);
  VkClearValue clears[3]{};
  clears[0].color.float32[0] = 3.0e38f;  // nothing: farther than anything
  clears[1].color.uint32[0] = 0;
  clears[2].depthStencil = {1.f, 0};
  VkViewport viewport{0.f, 0.f, float(width), float(height), 0.f, 1.f};
  VkRect2D scissor{{0, 0}, {width, height}};
  VkDeviceSize offset = 0;
  VkBuffer vertex_buffer = m_vertices.handle();
  for (uint32_t layer = 0; layer < layers; ++layer) {
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = m_pass;
    begin.framebuffer = m_framebuffers[layer];
    begin.renderArea = scissor;
    begin.clearValueCount = 3;
    begin.pClearValues = clears;
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_pipeline);
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertex_buffer, &offset);
    vkCmdBindIndexBuffer(cmd, m_indices.handle(), 0, VK_INDEX_TYPE_UINT32);
    ViewConstants constants = view_constants(views[layer]);
    vkCmdPushConstants(cmd, m_layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(constants), &constants);
    vkCmdDrawIndexed(cmd, 3 * m_triangles, 1, 0, 0, 0);
    vkCmdEndRenderPass(cmd);
  }
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers};
  region.imageExtent = {width, height, 1};
  vkCmdCopyImageToBuffer(cmd, m_distance.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, distances.handle(), 1, &region);
  vkCmdCopyImageToBuffer(cmd, m_triangle.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, triangles.handle(), 1, &region);
}

} // namespace hilight::ism

#include "triangle_raster.hpp"

#include "compute_kernel.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>

namespace hilight::ism {

namespace {

constexpr VkFormat kTriangleFormat = VK_FORMAT_R32_UINT;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

struct ViewConstants {
  float view_projection[16];  // column-major, as GLSL reads a mat4
  uint32_t first_triangle;
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
  return c;
}

VkRenderPass create_pass(VkDevice device) {
  std::array<VkAttachmentDescription, 2> attachments{};
  const VkFormat formats[2] = {kTriangleFormat, kDepthFormat};
  for (int k = 0; k < 2; ++k) {
    attachments[k].format = formats[k];
    attachments[k].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[k].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    attachments[k].storeOp = k == 0 ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[k].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[k].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[k].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    attachments[k].finalLayout = k == 0 ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  }
  VkAttachmentReference colour{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depth{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colour;
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

TriangleRaster::TriangleRaster(VulkanContext& context, const Buffer& vertices, std::span<const uint32_t> vertex_spirv,
                               std::span<const uint32_t> fragment_spirv)
    : m_context(context), m_vertices(vertices) {
  VkDevice device = context.device();
  try {
    m_pass = create_pass(device);
    m_vertex = create_shader_module(context, vertex_spirv);
    m_fragment = create_shader_module(context, fragment_spirv);
    VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(ViewConstants)};
    VkDescriptorSetLayoutBinding ids{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo set{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    set.bindingCount = 1;
    set.pBindings = &ids;
    check(vkCreateDescriptorSetLayout(device, &set, nullptr, &m_set_layout), "vkCreateDescriptorSetLayout");
    VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout.setLayoutCount = 1;
    layout.pSetLayouts = &m_set_layout;
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
    VkPipelineColorBlendAttachmentState blend{};
    blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT;
    VkPipelineColorBlendStateCreateInfo blending{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blending.attachmentCount = 1;
    blending.pAttachments = &blend;
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

TriangleRaster::~TriangleRaster() { release(); }

void TriangleRaster::release() {
  VkDevice device = m_context.device();
  release_targets();
  if (m_pipeline) vkDestroyPipeline(device, m_pipeline, nullptr);
  if (m_layout) vkDestroyPipelineLayout(device, m_layout, nullptr);
  if (m_set_layout) vkDestroyDescriptorSetLayout(device, m_set_layout, nullptr);
  if (m_vertex) vkDestroyShaderModule(device, m_vertex, nullptr);
  if (m_fragment) vkDestroyShaderModule(device, m_fragment, nullptr);
  if (m_pass) vkDestroyRenderPass(device, m_pass, nullptr);
  m_pipeline = VK_NULL_HANDLE;
  m_layout = VK_NULL_HANDLE;
  m_set_layout = VK_NULL_HANDLE;
  m_vertex = m_fragment = VK_NULL_HANDLE;
  m_pass = VK_NULL_HANDLE;
}

void TriangleRaster::release_targets() {
  if (m_framebuffer) vkDestroyFramebuffer(m_context.device(), m_framebuffer, nullptr);
  m_framebuffer = VK_NULL_HANDLE;
  m_triangle.reset();
  m_depth.reset();
}

void TriangleRaster::make_targets(uint32_t width, uint32_t height) {
  if (m_triangle.handle() && m_triangle.width() == width && m_triangle.height() == height) return;
  release_targets();
  const VkImageUsageFlags colour = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  m_triangle = DeviceImage(m_context, kTriangleFormat, colour, VK_IMAGE_ASPECT_COLOR_BIT, width, height, 1, "shadow maps (triangle ids)");
  m_depth = DeviceImage(m_context, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT, width,
                        height, 1, "depth buffer");
  VkImageView views[2] = {m_triangle.layer_view(0), m_depth.layer_view(0)};
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = m_pass;
  info.attachmentCount = 2;
  info.pAttachments = views;
  info.width = width;
  info.height = height;
  info.layers = 1;
  check(vkCreateFramebuffer(m_context.device(), &info, nullptr, &m_framebuffer), "vkCreateFramebuffer");
}

uint32_t TriangleRaster::max_views(VulkanContext& context, uint32_t width, uint32_t height) {
  const uint32_t limit = context.properties().limits.maxImageDimension2D;
  return std::min(kColumns, limit / width) * (limit / height);
}

void TriangleRaster::record(VkCommandBuffer cmd, std::span<const RasterView> views, std::span<const RasterDraw> draws,
                            const Buffer& indices, const Buffer& triangle_ids, uint32_t width, uint32_t height,
                            const Buffer& triangles) {
  if (draws.size() != views.size()) throw std::logic_error("TriangleRaster: one draw per view");
  if (views.size() > max_views(m_context, width, height)) throw std::logic_error("TriangleRaster: too many views for one atlas");
  // All views are tiles of one atlas, drawn in one render pass: lavapipe
  // pays a flush per render pass, far more than per draw.
  const uint32_t count = uint32_t(views.size());
  const uint32_t columns = std::min(count, kColumns), rows = (count + columns - 1) / columns;
  make_targets(columns * width, rows * height);
  VkClearValue clears[2]{};
  clears[0].color.uint32[0] = 0;  // nothing
  clears[1].depthStencil = {1.f, 0};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = m_pass;
  begin.framebuffer = m_framebuffer;
  begin.renderArea = {{0, 0}, {columns * width, rows * height}};
  begin.clearValueCount = 2;
  begin.pClearValues = clears;
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_pipeline);
  VkDeviceSize offset = 0;
  VkBuffer vertex_buffer = m_vertices.handle();
  vkCmdBindVertexBuffers(cmd, 0, 1, &vertex_buffer, &offset);
  vkCmdBindIndexBuffer(cmd, indices.handle(), 0, VK_INDEX_TYPE_UINT32);
  VkDescriptorBufferInfo ids{triangle_ids.handle(), 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstBinding = 0;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  write.pBufferInfo = &ids;
  m_context.push_descriptor_set(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, m_layout, 0, 1, &write);
  std::vector<VkBufferImageCopy> regions(count);
  for (uint32_t k = 0; k < count; ++k) {
    const int32_t x = int32_t((k % columns) * width), y = int32_t((k / columns) * height);
    VkViewport viewport{float(x), float(y), float(width), float(height), 0.f, 1.f};
    VkRect2D scissor{{x, y}, {width, height}};  // the tile: nothing spills into a neighbour
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    ViewConstants constants = view_constants(views[k]);
    constants.first_triangle = draws[k].first;
    vkCmdPushConstants(cmd, m_layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(constants), &constants);
    if (draws[k].count) vkCmdDrawIndexed(cmd, 3 * draws[k].count, 1, 3 * draws[k].first, 0, 0);
    // Each tile lands in the buffer as its own width x height block.
    regions[k].bufferOffset = VkDeviceSize(k) * width * height * 4;
    regions[k].imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    regions[k].imageOffset = {x, y, 0};
    regions[k].imageExtent = {width, height, 1};
  }
  vkCmdEndRenderPass(cmd);
  vkCmdCopyImageToBuffer(cmd, m_triangle.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, triangles.handle(), count, regions.data());
}

} // namespace hilight::ism

#include "compute_kernel.hpp"

#include "hilight/error.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace hilight::ism {

VkShaderModule create_shader_module(VulkanContext& context, std::span<const uint32_t> spirv) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  check(vkCreateShaderModule(context.device(), &info, nullptr, &module), "vkCreateShaderModule");
  return module;
}

ComputeKernel::ComputeKernel(VulkanContext& context, std::span<const uint32_t> spirv, uint32_t buffer_count,
                             uint32_t push_bytes, uint32_t workgroup_width)
    : m_context(context), m_buffer_count(buffer_count), m_push_bytes(push_bytes), m_width(workgroup_width) {
  VkDevice device = context.device();
  try {
    m_module = create_shader_module(context, spirv);
    std::vector<VkDescriptorSetLayoutBinding> bindings(buffer_count);
    for (uint32_t b = 0; b < buffer_count; ++b)
      bindings[b] = {b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo set{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    set.bindingCount = buffer_count;
    set.pBindings = bindings.data();
    check(vkCreateDescriptorSetLayout(device, &set, nullptr, &m_set_layout), "vkCreateDescriptorSetLayout");
    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, push_bytes};
    VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout.setLayoutCount = 1;
    layout.pSetLayouts = &m_set_layout;
    layout.pushConstantRangeCount = push_bytes ? 1 : 0;
    layout.pPushConstantRanges = &range;
    check(vkCreatePipelineLayout(device, &layout, nullptr, &m_layout), "vkCreatePipelineLayout");
    VkSpecializationMapEntry entry{0, 0, sizeof(uint32_t)};
    VkSpecializationInfo specialization{1, &entry, sizeof(uint32_t), &m_width};
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = m_module;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = &specialization;
    info.layout = m_layout;
    check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &m_pipeline), "vkCreateComputePipelines");
  } catch (...) {
    release();
    throw;
  }
}

ComputeKernel::~ComputeKernel() { release(); }

void ComputeKernel::release() {
  VkDevice device = m_context.device();
  if (m_pipeline) vkDestroyPipeline(device, m_pipeline, nullptr);
  if (m_layout) vkDestroyPipelineLayout(device, m_layout, nullptr);
  if (m_set_layout) vkDestroyDescriptorSetLayout(device, m_set_layout, nullptr);
  if (m_module) vkDestroyShaderModule(device, m_module, nullptr);
  m_pipeline = VK_NULL_HANDLE;
  m_layout = VK_NULL_HANDLE;
  m_set_layout = VK_NULL_HANDLE;
  m_module = VK_NULL_HANDLE;
}

void ComputeKernel::dispatch(VkCommandBuffer cmd, std::initializer_list<const Buffer*> buffers, const void* push,
                             uint64_t invocations) const {
  if (invocations == 0) return;
  if (buffers.size() != m_buffer_count) throw std::logic_error("ComputeKernel: wrong number of buffers");
  std::vector<VkDescriptorBufferInfo> infos;
  std::vector<VkWriteDescriptorSet> writes;
  infos.reserve(buffers.size());
  for (const Buffer* b : buffers) infos.push_back({b->handle(), 0, VK_WHOLE_SIZE});
  for (uint32_t i = 0; i < m_buffer_count; ++i) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstBinding = i;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    w.pBufferInfo = &infos[i];
    writes.push_back(w);
  }
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipeline);
  m_context.push_descriptor_set(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_layout, 0, uint32_t(writes.size()), writes.data());
  if (m_push_bytes) vkCmdPushConstants(cmd, m_layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, m_push_bytes, push);
  const uint64_t groups = (invocations + m_width - 1) / m_width;
  const uint64_t max_x = m_context.properties().limits.maxComputeWorkGroupCount[0];
  const uint64_t x = std::min(groups, max_x);
  const uint64_t y = (groups + x - 1) / x;
  if (y > m_context.properties().limits.maxComputeWorkGroupCount[1])
    throw InputError("renderer ism-vulkan: a dispatch of " + std::to_string(invocations) +
                     " threads exceeds the device's limits; lower vpls or points_per_vpl");
  vkCmdDispatch(cmd, uint32_t(x), uint32_t(y), 1);
}

void full_barrier(VkCommandBuffer cmd) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT |
                          VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT | VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &barrier, 0, nullptr, 0, nullptr);
}

} // namespace hilight::ism

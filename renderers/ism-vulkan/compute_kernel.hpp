#pragma once
/// A compute shader as a pipeline: its bindings are storage buffers 0..n-1
/// (pushed per dispatch, no descriptor pools), its parameters a push-constant
/// block, its work-group width a specialization constant.
#include "vulkan_resources.hpp"

#include <cstdint>
#include <initializer_list>
#include <span>

namespace hilight::ism {

class ComputeKernel {
public:
  ComputeKernel(VulkanContext& context, std::span<const uint32_t> spirv, uint32_t buffer_count, uint32_t push_bytes,
                uint32_t workgroup_width);
  ~ComputeKernel();
  ComputeKernel(const ComputeKernel&) = delete;
  ComputeKernel& operator=(const ComputeKernel&) = delete;

  /// Records one dispatch of at least `invocations` threads (the shader gets
  /// the count in its push constants and ignores the rest); the groups are
  /// laid out in 2D when one dimension would exceed the device's limit.
  void dispatch(VkCommandBuffer cmd, std::initializer_list<const Buffer*> buffers, const void* push,
                uint64_t invocations) const;

private:
  void release();

  VulkanContext& m_context;
  uint32_t m_buffer_count, m_push_bytes, m_width;
  VkShaderModule m_module = VK_NULL_HANDLE;
  VkDescriptorSetLayout m_set_layout = VK_NULL_HANDLE;
  VkPipelineLayout m_layout = VK_NULL_HANDLE;
  VkPipeline m_pipeline = VK_NULL_HANDLE;
};

/// Makes every earlier shader/transfer write visible to every later read or write.
void full_barrier(VkCommandBuffer cmd);

VkShaderModule create_shader_module(VulkanContext& context, std::span<const uint32_t> spirv);

} // namespace hilight::ism

#pragma once
/// Owning wrappers of Vulkan buffers and images: destroyed with their owner,
/// memory booked against the context's budget so an oversized request fails
/// with a clear error before the device is asked.
#include "vulkan_context.hpp"

#include <string>
#include <utility>
#include <vector>

namespace hilight::ism {

class Buffer {
public:
  Buffer() = default;
  /// Host-visible buffers are mapped (uploads, read-backs); the others stay
  /// on the device (intermediate results).
  Buffer(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage, bool host_visible, const std::string& what);
  ~Buffer() { reset(); }
  Buffer(Buffer&& other) noexcept { *this = std::move(other); }
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return m_buffer; }
  VkDeviceSize size() const { return m_size; }
  template <class T> T* data() const { return static_cast<T*>(m_mapped); }
  explicit operator bool() const { return m_buffer != VK_NULL_HANDLE; }
  void reset();

private:
  VulkanContext* m_context = nullptr;
  VkBuffer m_buffer = VK_NULL_HANDLE;
  VkDeviceMemory m_memory = VK_NULL_HANDLE;
  VkDeviceSize m_size = 0, m_booked = 0;
  void* m_mapped = nullptr;
};

/// A 2D image with `layers` array layers and one view per layer (render targets).
class DeviceImage {
public:
  DeviceImage() = default;
  DeviceImage(VulkanContext& context, VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect, uint32_t width,
        uint32_t height, uint32_t layers, const std::string& what);
  ~DeviceImage() { reset(); }
  DeviceImage(DeviceImage&& other) noexcept { *this = std::move(other); }
  DeviceImage& operator=(DeviceImage&& other) noexcept;
  DeviceImage(const DeviceImage&) = delete;
  DeviceImage& operator=(const DeviceImage&) = delete;

  VkImage handle() const { return m_image; }
  VkImageView layer_view(uint32_t layer) const { return m_views[layer]; }
  uint32_t width() const { return m_width; }
  uint32_t height() const { return m_height; }
  uint32_t layers() const { return uint32_t(m_views.size()); }
  VkImageAspectFlags aspect() const { return m_aspect; }
  void reset();

private:
  VulkanContext* m_context = nullptr;
  VkImage m_image = VK_NULL_HANDLE;
  VkDeviceMemory m_memory = VK_NULL_HANDLE;
  std::vector<VkImageView> m_views;
  VkDeviceSize m_booked = 0;
  uint32_t m_width = 0, m_height = 0;
  VkImageAspectFlags m_aspect = 0;
};

} // namespace hilight::ism

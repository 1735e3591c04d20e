#include "vulkan_resources.hpp"

#include "hilight/error.hpp"

#include <algorithm>

namespace hilight::ism {

namespace {

VkDeviceMemory allocate(VulkanContext& context, const VkMemoryRequirements& needs, bool host_visible) {
  uint32_t type = ~0u;
  if (host_visible) {
    const VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    type = context.memory_type(needs.memoryTypeBits, host | VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (type == ~0u) type = context.memory_type(needs.memoryTypeBits, host);
  } else {
    type = context.memory_type(needs.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (type == ~0u) type = context.memory_type(needs.memoryTypeBits, 0);
  }
  if (type == ~0u) throw VulkanError("renderer ism-vulkan: no suitable memory type");
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.allocationSize = needs.size;
  info.memoryTypeIndex = type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  check(vkAllocateMemory(context.device(), &info, nullptr, &memory), "vkAllocateMemory");
  return memory;
}

} // namespace

Buffer::Buffer(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage, bool host_visible,
               const std::string& what)
    : m_context(&context), m_size(size) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = std::max<VkDeviceSize>(size, 16);
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  context.reserve_memory(info.size, what);
  m_booked = info.size;
  try {
    check(vkCreateBuffer(context.device(), &info, nullptr, &m_buffer), "vkCreateBuffer");
    VkMemoryRequirements needs;
    vkGetBufferMemoryRequirements(context.device(), m_buffer, &needs);
    m_memory = allocate(context, needs, host_visible);
    check(vkBindBufferMemory(context.device(), m_buffer, m_memory, 0), "vkBindBufferMemory");
    if (host_visible) check(vkMapMemory(context.device(), m_memory, 0, VK_WHOLE_SIZE, 0, &m_mapped), "vkMapMemory");
  } catch (...) {
    reset();
    throw;
  }
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    reset();
    std::swap(m_context, other.m_context);
    std::swap(m_buffer, other.m_buffer);
    std::swap(m_memory, other.m_memory);
    std::swap(m_size, other.m_size);
    std::swap(m_booked, other.m_booked);
    std::swap(m_mapped, other.m_mapped);
  }
  return *this;
}

void Buffer::reset() {
  if (!m_context) return;
  VkDevice device = m_context->device();
  if (m_mapped) vkUnmapMemory(device, m_memory);
  if (m_buffer) vkDestroyBuffer(device, m_buffer, nullptr);
  if (m_memory) vkFreeMemory(device, m_memory, nullptr);
  m_context->release_memory(m_booked);
  m_context = nullptr;
  m_buffer = VK_NULL_HANDLE;
  m_memory = VK_NULL_HANDLE;
  m_mapped = nullptr;
  m_size = m_booked = 0;
}

DeviceImage::DeviceImage(VulkanContext& context, VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect, uint32_t width,
             uint32_t height, uint32_t layers, const std::string& what)
    : m_context(&context), m_width(width), m_height(height), m_aspect(aspect) {
  const auto& limits = context.properties().limits;
  if (width > limits.maxImageDimension2D || height > limits.maxImageDimension2D || layers > limits.maxImageArrayLayers)
    throw InputError("renderer ism-vulkan: " + what + " of " + std::to_string(width) + "x" + std::to_string(height) + "x" +
                     std::to_string(layers) + " exceeds the device's image limits (" +
                     std::to_string(limits.maxImageDimension2D) + " pixels, " + std::to_string(limits.maxImageArrayLayers) +
                     " layers)");
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = 1;
  info.arrayLayers = layers;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  try {
    check(vkCreateImage(context.device(), &info, nullptr, &m_image), "vkCreateImage");
    VkMemoryRequirements needs;
    vkGetImageMemoryRequirements(context.device(), m_image, &needs);
    context.reserve_memory(needs.size, what);
    m_booked = needs.size;
    m_memory = allocate(context, needs, false);
    check(vkBindImageMemory(context.device(), m_image, m_memory, 0), "vkBindImageMemory");
    for (uint32_t layer = 0; layer < layers; ++layer) {
      VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
      view.image = m_image;
      view.viewType = VK_IMAGE_VIEW_TYPE_2D;
      view.format = format;
      view.subresourceRange = {aspect, 0, 1, layer, 1};
      VkImageView handle = VK_NULL_HANDLE;
      check(vkCreateImageView(context.device(), &view, nullptr, &handle), "vkCreateImageView");
      m_views.push_back(handle);
    }
  } catch (...) {
    reset();
    throw;
  }
}

DeviceImage& DeviceImage::operator=(DeviceImage&& other) noexcept {
  if (this != &other) {
    reset();
    std::swap(m_context, other.m_context);
    std::swap(m_image, other.m_image);
    std::swap(m_memory, other.m_memory);
    std::swap(m_views, other.m_views);
    std::swap(m_booked, other.m_booked);
    std::swap(m_width, other.m_width);
    std::swap(m_height, other.m_height);
    std::swap(m_aspect, other.m_aspect);
  }
  return *this;
}

void DeviceImage::reset() {
  if (!m_context) return;
  VkDevice device = m_context->device();
  for (auto v : m_views) vkDestroyImageView(device, v, nullptr);
  m_views.clear();
  if (m_image) vkDestroyImage(device, m_image, nullptr);
  if (m_memory) vkFreeMemory(device, m_memory, nullptr);
  m_context->release_memory(m_booked);
  m_context = nullptr;
  m_image = VK_NULL_HANDLE;
  m_memory = VK_NULL_HANDLE;
  m_booked = 0;
}

} // namespace hilight::ism

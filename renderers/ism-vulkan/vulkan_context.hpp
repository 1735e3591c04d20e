#pragma once
/// One headless Vulkan device for the ism-vulkan renderer: instance (with the
/// validation layer on request), the chosen physical device (a discrete GPU
/// when present, else integrated, virtual, then CPU = Mesa lavapipe), one
/// queue that does graphics and compute, a command pool, and memory types.
#include <vulkan/vulkan.h>

#include <atomic>
#include <stdexcept>
#include <string>

namespace hilight::ism {

/// A Vulkan call failed; the message names the call and the VkResult.
struct VulkanError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Throws VulkanError (or InputError for out-of-memory, which is a request
/// the device cannot serve) unless `result` is VK_SUCCESS.
void check(VkResult result, const char* what);
const char* result_name(VkResult result);

struct DeviceOptions {
  bool validation = false;     ///< enable VK_LAYER_KHRONOS_validation; errors become exceptions
  std::string device = "auto"; ///< auto | gpu | cpu | index into the device list
};

class VulkanContext {
public:
  explicit VulkanContext(const DeviceOptions& options);
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkDevice device() const { return m_device; }
  VkPhysicalDevice physical() const { return m_physical; }
  VkQueue queue() const { return m_queue; }
  VkCommandPool command_pool() const { return m_pool; }
  const VkPhysicalDeviceProperties& properties() const { return m_properties; }
  /// "llvmpipe (LLVM 15.0.6, 256 bits), cpu" and the like.
  std::string description() const;
  bool is_cpu() const { return m_properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }

  /// A memory type allowed by `type_bits` with all of `wanted`, or ~0u.
  uint32_t memory_type(uint32_t type_bits, VkMemoryPropertyFlags wanted) const;
  /// Largest single allocation the device accepts, and the size of its largest heap.
  VkDeviceSize max_allocation() const { return m_max_allocation; }
  VkDeviceSize largest_heap() const { return m_largest_heap; }

  /// Device memory this renderer may hold at once: the smaller of
  /// `limit_bytes` (0: no own limit) and 3/4 of the largest heap.
  void set_memory_budget(VkDeviceSize limit_bytes);
  /// Books `bytes` for `what`; InputError naming it when over the budget or
  /// beyond the device's largest allocation.
  void reserve_memory(VkDeviceSize bytes, const std::string& what);
  void release_memory(VkDeviceSize bytes) { m_allocated -= bytes; }

  PFN_vkCmdPushDescriptorSetKHR push_descriptor_set = nullptr;

  /// Throws VulkanError with the first validation error reported since the
  /// last call (only when validation is on); clears the record.
  void throw_on_validation_errors();
  size_t validation_errors() const { return m_validation_errors.load(); }

  /// Records the validation layer's report (called by the debug callback).
  void report_validation_error(const char* message);

private:
  void release();

  VkInstance m_instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT m_messenger = VK_NULL_HANDLE;
  VkPhysicalDevice m_physical = VK_NULL_HANDLE;
  VkDevice m_device = VK_NULL_HANDLE;
  VkQueue m_queue = VK_NULL_HANDLE;
  uint32_t m_queue_family = 0;
  VkCommandPool m_pool = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties m_properties{};
  VkPhysicalDeviceMemoryProperties m_memory{};
  VkDeviceSize m_max_allocation = 0, m_largest_heap = 0;
  VkDeviceSize m_budget = 0, m_allocated = 0;
  std::atomic<size_t> m_validation_errors{0};
  std::string m_first_validation_error;
  bool m_pending_validation_error = false;
};

/// Why no Vulkan device can be used here ("" when one can), and which one
/// would be picked: for `hilight plugins` and the tests' skip reasons.
std::string vulkan_unavailable_reason();
std::string vulkan_device_summary();

} // namespace hilight::ism

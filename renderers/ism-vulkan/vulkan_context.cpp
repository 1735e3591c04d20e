#include "vulkan_context.hpp"

#include "hilight/error.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <vector>

namespace hilight::ism {

namespace {

std::mutex g_validation_mutex;

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                     VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT)
    static_cast<VulkanContext*>(user)->report_validation_error(data->pMessage ? data->pMessage : "(no message)");
  return VK_FALSE;
}

bool has_layer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const auto& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool has_device_extension(VkPhysicalDevice device, const char* name) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(), [&](const auto& e) { return std::strcmp(e.extensionName, name) == 0; });
}

/// The queue family that does graphics and compute, or ~0u.
uint32_t graphics_compute_family(VkPhysicalDevice device) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (uint32_t i = 0; i < count; ++i)
    if ((families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) return i;
  return ~0u;
}

int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
  case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 4;
  case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 3;
  case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
  case VK_PHYSICAL_DEVICE_TYPE_CPU: return 1;
  default: return 0;
  }
}

const char* type_name(VkPhysicalDeviceType type) {
  switch (type) {
  case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete gpu";
  case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated gpu";
  case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual gpu";
  case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
  default: return "other";
  }
}

VkInstance create_instance(bool validation) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "hilight";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  const char* layer = "VK_LAYER_KHRONOS_validation";
  const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  if (validation) {
    if (!has_layer(layer))
      throw InputError("renderer ism-vulkan: validation requested but VK_LAYER_KHRONOS_validation is not installed "
                       "(Debian package vulkan-validationlayers)");
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &layer;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &extension;
  }
  VkInstance instance = VK_NULL_HANDLE;
  VkResult r = vkCreateInstance(&info, nullptr, &instance);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER) throw VulkanError("no Vulkan driver (install mesa-vulkan-drivers for lavapipe)");
  check(r, "vkCreateInstance");
  return instance;
}

struct Candidate {
  VkPhysicalDevice device;
  VkPhysicalDeviceProperties properties;
  uint32_t family;
};

/// Usable devices (graphics+compute queue, push descriptors), best first.
std::vector<Candidate> usable_devices(VkInstance instance) {
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  std::vector<Candidate> out;
  for (auto d : devices) {
    Candidate c{d, {}, graphics_compute_family(d)};
    vkGetPhysicalDeviceProperties(d, &c.properties);
    if (c.family == ~0u || c.properties.apiVersion < VK_API_VERSION_1_1) continue;
    if (!has_device_extension(d, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME)) continue;
    out.push_back(c);
  }
  std::stable_sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
    return type_rank(a.properties.deviceType) > type_rank(b.properties.deviceType);
  });
  return out;
}

Candidate choose(const std::vector<Candidate>& devices, const std::string& wanted) {
  if (devices.empty()) throw VulkanError("no Vulkan device with graphics, compute and push descriptors");
  if (wanted == "auto") return devices.front();
  if (wanted == "cpu" || wanted == "gpu") {
    for (const auto& c : devices)
      if ((c.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) == (wanted == "cpu")) return c;
    throw InputError("renderer ism-vulkan: device=" + wanted + ": no such Vulkan device here");
  }
  char* end = nullptr;
  unsigned long index = std::strtoul(wanted.c_str(), &end, 10);
  if (wanted.empty() || *end || index >= devices.size())
    throw InputError("renderer ism-vulkan: device must be auto, gpu, cpu or an index below " + std::to_string(devices.size()));
  return devices[index];
}

} // namespace

const char* result_name(VkResult result) {
  switch (result) {
  case VK_SUCCESS: return "VK_SUCCESS";
  case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
  case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
  case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
  case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
  case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
  case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
  case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
  case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
  case VK_ERROR_TOO_MANY_OBJECTS: return "VK_ERROR_TOO_MANY_OBJECTS";
  case VK_ERROR_FORMAT_NOT_SUPPORTED: return "VK_ERROR_FORMAT_NOT_SUPPORTED";
  case VK_TIMEOUT: return "VK_TIMEOUT";
  default: return "VkResult error";
  }
}

void check(VkResult result, const char* what) {
  if (result == VK_SUCCESS) return;
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
    throw InputError(std::string("renderer ism-vulkan: the device ran out of memory (") + what +
                     "); lower shadow_size, vpls, ism_size or chunk_mb");
  throw VulkanError(std::string("renderer ism-vulkan: ") + what + " failed: " + result_name(result));
}

VulkanContext::VulkanContext(const DeviceOptions& options) {
  try {
    m_instance = create_instance(options.validation);
    if (options.validation) {
      VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
      info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
      info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                         VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
      info.pfnUserCallback = on_validation_message;
      info.pUserData = this;
      auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(m_instance, "vkCreateDebugUtilsMessengerEXT"));
      if (!create) throw VulkanError("renderer ism-vulkan: vkCreateDebugUtilsMessengerEXT missing");
      check(create(m_instance, &info, nullptr, &m_messenger), "vkCreateDebugUtilsMessengerEXT");
    }
    Candidate chosen = choose(usable_devices(m_instance), options.device);
    m_physical = chosen.device;
    m_properties = chosen.properties;
    m_queue_family = chosen.family;
    vkGetPhysicalDeviceMemoryProperties(m_physical, &m_memory);
    for (uint32_t h = 0; h < m_memory.memoryHeapCount; ++h) m_largest_heap = std::max(m_largest_heap, m_memory.memoryHeaps[h].size);
    VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
    VkPhysicalDeviceProperties2 properties2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties2.pNext = &maintenance3;
    vkGetPhysicalDeviceProperties2(m_physical, &properties2);
    m_max_allocation = maintenance3.maxMemoryAllocationSize;
    set_memory_budget(0);

    float priority = 1.f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = m_queue_family;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    const char* extension = VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME;
    // The raster names triangles by gl_PrimitiveID in its fragment stage,
    // which Vulkan ties to the geometry-shader feature.
    VkPhysicalDeviceFeatures supported{}, features{};
    vkGetPhysicalDeviceFeatures(m_physical, &supported);
    if (!supported.geometryShader) throw VulkanError("renderer ism-vulkan: the device lacks the geometryShader feature");
    features.geometryShader = VK_TRUE;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pEnabledFeatures = &features;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &extension;
    check(vkCreateDevice(m_physical, &info, nullptr, &m_device), "vkCreateDevice");
    vkGetDeviceQueue(m_device, m_queue_family, 0, &m_queue);
    push_descriptor_set =
        reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(vkGetDeviceProcAddr(m_device, "vkCmdPushDescriptorSetKHR"));
    if (!push_descriptor_set) throw VulkanError("renderer ism-vulkan: vkCmdPushDescriptorSetKHR missing");

    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = m_queue_family;
    check(vkCreateCommandPool(m_device, &pool, nullptr, &m_pool), "vkCreateCommandPool");
  } catch (...) {
    release();
    throw;
  }
}

VulkanContext::~VulkanContext() { release(); }

void VulkanContext::release() {
  if (m_device) {
    vkDeviceWaitIdle(m_device);
    if (m_pool) vkDestroyCommandPool(m_device, m_pool, nullptr);
    vkDestroyDevice(m_device, nullptr);
  }
  if (m_messenger) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(m_instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(m_instance, m_messenger, nullptr);
  }
  if (m_instance) vkDestroyInstance(m_instance, nullptr);
  // Objects still alive at vkDestroyDevice are reported by the validation
  // layer now, when no call is left to fail: say so on stderr (tests read it).
  if (m_pending_validation_error)
    std::fprintf(stderr, "hilight: Vulkan validation error at shutdown: %s\n", m_first_validation_error.c_str());
  m_pending_validation_error = false;
  m_pool = VK_NULL_HANDLE;
  m_device = VK_NULL_HANDLE;
  m_messenger = VK_NULL_HANDLE;
  m_instance = VK_NULL_HANDLE;
}

std::string VulkanContext::description() const {
  return std::string(m_properties.deviceName) + ", " + type_name(m_properties.deviceType);
}

uint32_t VulkanContext::memory_type(uint32_t type_bits, VkMemoryPropertyFlags wanted) const {
  for (uint32_t i = 0; i < m_memory.memoryTypeCount; ++i)
    if ((type_bits & (1u << i)) && (m_memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
  return ~0u;
}

void VulkanContext::set_memory_budget(VkDeviceSize limit_bytes) {
  m_budget = m_largest_heap / 4 * 3;
  if (limit_bytes > 0) m_budget = std::min(m_budget, limit_bytes);
}

void VulkanContext::reserve_memory(VkDeviceSize bytes, const std::string& what) {
  auto mb = [](VkDeviceSize b) { return std::to_string((b + (1u << 20) - 1) >> 20) + " MB"; };
  if (bytes > m_max_allocation)
    throw InputError("renderer ism-vulkan: " + what + " needs " + mb(bytes) + " in one allocation; the device allows " +
                     mb(m_max_allocation));
  if (m_budget && m_allocated + bytes > m_budget)
    throw InputError("renderer ism-vulkan: " + what + " needs " + mb(bytes) + " more device memory; " + mb(m_allocated) +
                     " of the " + mb(m_budget) + " budget are in use (the scene or the settings are too large for this device)");
  m_allocated += bytes;
}

void VulkanContext::report_validation_error(const char* message) {
  std::lock_guard lock(g_validation_mutex);
  ++m_validation_errors;
  if (!m_pending_validation_error) m_first_validation_error = message;
  m_pending_validation_error = true;
}

void VulkanContext::throw_on_validation_errors() {
  std::lock_guard lock(g_validation_mutex);
  if (!m_pending_validation_error) return;
  m_pending_validation_error = false;
  throw VulkanError("renderer ism-vulkan: Vulkan validation error: " + m_first_validation_error);
}

std::string vulkan_unavailable_reason() {
  try {
    VulkanContext context(DeviceOptions{});
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

std::string vulkan_device_summary() {
  try {
    VulkanContext context(DeviceOptions{});
    return context.description();
  } catch (const std::exception& e) {
    return std::string("unavailable: ") + e.what();
  }
}

} // namespace hilight::ism

#include "hilight/threads.hpp"

#include <memory>
#include <tbb/global_control.h>

namespace hilight {

void set_thread_limit(int threads) {
  static std::unique_ptr<tbb::global_control> control;
  control.reset();
  if (threads > 0) control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, size_t(threads));
}

} // namespace hilight

#pragma once
/// Process-wide thread limit (the --threads option of every command).
namespace hilight {
/// Limits TBB parallelism to `threads` (0 = all cores). Lasts for the process.
void set_thread_limit(int threads);
} // namespace hilight

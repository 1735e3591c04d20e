#include "progress_display.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <sys/ioctl.h>
#include <unistd.h>
#include <utility>
#include <vector>

namespace hilight::cli {

std::string format_duration(double seconds) {
  char text[48];
  const long s = std::lround(std::max(0.0, seconds));
  if (s < 60)
    std::snprintf(text, sizeof(text), "%ld s", s);
  else if (s < 3600)
    std::snprintf(text, sizeof(text), "%ld min %02ld s", s / 60, s % 60);
  else
    std::snprintf(text, sizeof(text), "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  return text;
}

namespace {

enum class Mode { None, Bar, Lines };

/// Nothing is drawn for work shorter than this: a quick command stays quiet.
constexpr double kDrawAfter = 0.3;
/// Lines (--progress) at most this often, and whenever the stage changes.
constexpr double kLineInterval = 1.0;

bool stderr_is_terminal() {
  if (!::isatty(2)) return false;
  const char* term = std::getenv("TERM");
  return !(term && std::strcmp(term, "dumb") == 0);  // no cursor control there
}

int terminal_columns() {
  winsize w{};
  if (::ioctl(2, TIOCGWINSZ, &w) == 0 && w.ws_col >= 20) return w.ws_col;
  return 80;
}

void write_all(const std::string& text) {
  const char* p = text.data();
  size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(2, p, left);
    if (n <= 0) return;  // stderr gone: progress is not worth failing for
    p += n;
    left -= size_t(n);
  }
}

std::string stage_text(const std::vector<std::string>& stages) {
  std::string out;
  for (const auto& s : stages) out += (out.empty() ? "" : " › ") + s;
  return out;
}

/// Characters as a terminal counts them (UTF-8 continuation bytes are not).
size_t columns_of(const std::string& s) {
  size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

/// `s` cut to `columns` characters, never inside a UTF-8 sequence.
std::string cut_to(const std::string& s, size_t columns) {
  if (columns_of(s) <= columns) return s;
  size_t n = 0, i = 0;
  for (; i < s.size(); ++i)
    if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80 && n++ == columns - 1) break;
  return columns > 0 ? s.substr(0, i) + "…" : std::string();
}

} // namespace

class CommandProgress::Display final : public ProgressReporter {
public:
  explicit Display(Mode mode) : m_mode(mode) {}

  void update(const ProgressUpdate& now) override {
    if (m_mode == Mode::None || now.elapsed < kDrawAfter) return;
    if (m_mode == Mode::Bar) return draw_bar(now);
    const std::string text = stage_text(now.stages);
    const double t = now.elapsed;
    if (text == m_last_text && t - m_last_line < kLineInterval) return;
    char figures[96] = "";
    if (now.fraction >= 0 && now.seconds_left >= 0)
      std::snprintf(figures, sizeof(figures), ": %.0f%% (%s left)", 100.0 * now.fraction,
                    format_duration(std::ceil(now.seconds_left)).c_str());
    else if (now.fraction >= 0)
      std::snprintf(figures, sizeof(figures), ": %.0f%%", 100.0 * now.fraction);
    else
      std::snprintf(figures, sizeof(figures), " (%s)", format_duration(t).c_str());
    const std::string line = "hilight: progress: " + text + figures + "\n";
    if (line == m_last_line_text) return;
    write_all(line);
    m_last_line_text = line;
    m_last_text = text;
    m_last_line = t;
  }

  void stage_ended(const std::string& name, size_t depth, double seconds) override {
    if (depth != 0 || name.empty()) return;
    std::lock_guard lock(m_times_mutex);
    auto it = std::find_if(m_times.begin(), m_times.end(), [&](const auto& p) { return p.first == name; });
    if (it == m_times.end())
      m_times.emplace_back(name, seconds);
    else
      it->second += seconds;
  }

  void idle() override {
    if (m_drawn) write_all("\r\x1b[K");
    m_drawn = false;
    m_last_text.clear();
    m_last_line_text.clear();
    m_last_line = -1e9;
  }

  std::vector<std::pair<std::string, double>> times() const {
    std::lock_guard lock(m_times_mutex);
    return m_times;
  }

private:
  void draw_bar(const ProgressUpdate& now) {
    const int columns = terminal_columns() - 1;  // the last column would wrap on some terminals
    std::string tail;
    char figures[96];
    if (now.fraction >= 0) {
      constexpr int kBar = 16;
      const int filled = std::clamp(int(std::floor(now.fraction * kBar)), 0, kBar);
      std::string bar = "[" + std::string(size_t(filled), '#') + std::string(size_t(kBar - filled), '.') + "]";
      std::snprintf(figures, sizeof(figures), " %3.0f%%", 100.0 * now.fraction);
      tail = "  " + bar + figures;
      if (now.seconds_left >= 0) tail += "  " + format_duration(std::ceil(now.seconds_left)) + " left";
    } else {
      static const char kSpin[] = {'|', '/', '-', '\\'};
      std::snprintf(figures, sizeof(figures), "  %c %s", kSpin[m_spin++ % 4], format_duration(now.elapsed).c_str());
      tail = figures;
    }
    const std::string text = "hilight: " + stage_text(now.stages);
    const size_t room = size_t(std::max(0, columns - int(columns_of(tail))));
    write_all("\r" + cut_to(text, room) + tail + "\x1b[K");
    m_drawn = true;
  }

  Mode m_mode;
  bool m_drawn = false;
  unsigned m_spin = 0;
  std::string m_last_text, m_last_line_text;
  double m_last_line = -1e9;
  mutable std::mutex m_times_mutex;
  std::vector<std::pair<std::string, double>> m_times;  ///< outermost stages, in the order they first ended
};

namespace {
std::atomic<CommandProgress*> g_running{nullptr};
} // namespace

std::string command_time_summary(double seconds) {
  if (CommandProgress* p = g_running.load()) return p->time_summary();
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f s", seconds);
  return text;
}

void stop_command_progress() {
  if (CommandProgress* p = g_running.load()) p->stop();
}

CommandProgress::CommandProgress() : m_start(std::chrono::steady_clock::now()) { g_running.store(this); }

CommandProgress::~CommandProgress() {
  stop();
  CommandProgress* self = this;
  g_running.compare_exchange_strong(self, nullptr);
}

void CommandProgress::add_to(CLI::App& app) {
  app.add_flag("--progress", m_lines,
               "show progress also when stderr is not a terminal, as lines for scripts "
               "(\"hilight: progress: STAGE: 45% (12 s left)\"); on a terminal a bar is shown without it");
  app.add_flag("--no-progress", m_off, "no progress bar on a terminal");
}

void CommandProgress::start(bool quiet) {
  if (quiet) return;
  const Mode mode = m_off ? Mode::None : stderr_is_terminal() ? Mode::Bar : m_lines ? Mode::Lines : Mode::None;
  m_display = std::make_unique<Display>(mode);
  m_reporting.emplace(m_display.get());
}

void CommandProgress::stop() { m_reporting.reset(); }

double CommandProgress::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
}

std::string CommandProgress::time_summary() const {
  const double total = seconds();
  char text[64];
  std::snprintf(text, sizeof(text), "%.2f s", total);
  std::string out = text;
  if (!m_display) return out;
  auto parts = m_display->times();
  std::stable_sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  std::string named;
  int listed = 0;
  for (const auto& [name, seconds] : parts) {
    if (listed == 3 || seconds < 0.5 || seconds < 0.1 * total) break;
    std::snprintf(text, sizeof(text), " %.1f s", seconds);
    named += (listed++ ? ", " : "") + name + text;
  }
  return named.empty() ? out : out + " (" + named + ")";
}

} // namespace hilight::cli

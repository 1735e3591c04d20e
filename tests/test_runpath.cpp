// No built file searches the current folder for libraries (issue 35): CMake
// padded the build tree's RUNPATH with empty entries (":"), which the loader
// reads as the current folder, so a library planted where a user ran
// build/bin/hilight was loaded. Every ELF file of the build is read here, and
// a planted library is put to the test.
#include "support.hpp"

#include <catch2/catch.hpp>
#include <cstring>
#include <elf.h>
#include <fcntl.h>
#include <set>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

const fs::path kBuild = fs::path(HILIGHT_BINARY).parent_path().parent_path();

struct Dynamic {
  bool elf = false;
  std::vector<std::string> search;  ///< RUNPATH and RPATH strings
  std::vector<std::string> needed;
};

/// The dynamic section of a 64-bit ELF file, through its section headers.
Dynamic read_dynamic(const fs::path& path) {
  Dynamic d;
  const std::string bytes = test::read_file(path);
  if (bytes.size() < sizeof(Elf64_Ehdr) || std::memcmp(bytes.data(), ELFMAG, SELFMAG) != 0 || bytes[EI_CLASS] != ELFCLASS64) return d;
  d.elf = true;
  Elf64_Ehdr eh;
  std::memcpy(&eh, bytes.data(), sizeof(eh));
  auto section = [&](size_t i) {
    Elf64_Shdr sh{};
    if (eh.e_shoff + (i + 1) * sizeof(Elf64_Shdr) <= bytes.size()) std::memcpy(&sh, bytes.data() + eh.e_shoff + i * sizeof(sh), sizeof(sh));
    return sh;
  };
  for (size_t i = 0; i < eh.e_shnum; ++i) {
    const Elf64_Shdr sh = section(i);
    if (sh.sh_type != SHT_DYNAMIC) continue;
    const Elf64_Shdr strtab = section(sh.sh_link);
    for (size_t at = sh.sh_offset; at + sizeof(Elf64_Dyn) <= sh.sh_offset + sh.sh_size && at + sizeof(Elf64_Dyn) <= bytes.size();
         at += sizeof(Elf64_Dyn)) {
      Elf64_Dyn dyn;
      std::memcpy(&dyn, bytes.data() + at, sizeof(dyn));
      if (dyn.d_tag != DT_RUNPATH && dyn.d_tag != DT_RPATH && dyn.d_tag != DT_NEEDED) continue;
      const size_t name = strtab.sh_offset + dyn.d_un.d_val;
      const std::string text = name < bytes.size() ? std::string(bytes.c_str() + name) : "";
      (dyn.d_tag == DT_NEEDED ? d.needed : d.search).push_back(text);
    }
  }
  return d;
}

/// The built files: executables, the framework library, the plugin modules, the tests' own modules.
std::vector<fs::path> built_elf_files() {
  std::vector<fs::path> out;
  for (const char* sub : {"bin", "lib", "tests"}) {
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(kBuild / sub, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      if (it->is_directory() && (it->path().filename() == "CMakeFiles" || it->path().filename() == "output")) {
        it.disable_recursion_pending();
        continue;
      }
      if (!it->is_regular_file() || it->is_symlink() || it->path().extension() == ".o" || it->file_size() < 64) continue;
      std::string head = test::read_file(it->path()).substr(0, 4);
      if (head == ELFMAG) out.push_back(it->path());
    }
  }
  return out;
}

/// Runs `hilight args` in `dir`; its exit code.
int run_in(const fs::path& dir, const std::vector<std::string>& args) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, 0), ::dup2(null, 1), ::dup2(null, 2);
    std::vector<std::string> copy = args;
    std::vector<char*> argv = {const_cast<char*>(HILIGHT_BINARY)};
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(HILIGHT_BINARY, argv.data());
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

} // namespace

TEST_CASE("no built file's RUNPATH has an empty entry (the current folder)", "[security][build]") {
  const auto files = built_elf_files();
  CHECK(files.size() >= 5);  // the launcher, the framework, plugins, the tests
  for (const auto& file : files) {
    const Dynamic d = read_dynamic(file);
    for (const auto& path : d.search) {
      INFO(file << ": RUNPATH [" << path << "]");
      bool empty_entry = path.empty();
      for (size_t start = 0; start <= path.size();) {
        const size_t end = std::min(path.find(':', start), path.size());
        empty_entry |= end == start || path.compare(start, end - start, ".") == 0;
        start = end + 1;
      }
      CHECK_FALSE(empty_entry);
    }
  }
}

TEST_CASE("a library planted in the working folder is not loaded", "[security][build]") {
  const auto dir = test::output_dir("runpath_planted");
  // Under the name of every library the launcher, the framework and the
  // plugins need that is not the C library's own.
  std::set<std::string> names;
  for (const auto& file : built_elf_files())
    for (const auto& name : read_dynamic(file).needed)
      if (name.rfind("libc.so", 0) != 0 && name.rfind("ld-linux", 0) != 0) names.insert(name);
  REQUIRE(names.size() > 3);
  for (const auto& name : names) fs::copy_file(HILIGHT_TEST_PLANTED_LIBRARY, dir / name);
  CHECK(run_in(dir, {"--version"}) == 0);
  CHECK(run_in(dir, {"plugins"}) == 0);
  CHECK_FALSE(fs::exists(dir / "planted-library-ran"));
}

// Every output goes through write_atomically (issue 35): a planted symlink at
// a temporary's name is never followed, a device or FIFO is written in place
// and never replaced, and a write that fails (a full disk) is one line naming
// the file, a non-zero exit, and nothing under the final name.
#include "hilight/error.hpp"
#include "hilight/io/atomic_file.hpp"
#include "photometry_files.hpp"
#include "support.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>
#include <csignal>
#include <fstream>
#include <fcntl.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using hilight::write_atomically;

namespace {

const std::string kRoom = HILIGHT_SOURCE_DIR "/scenes/room.obj";
const std::string kRoomLights = HILIGHT_SOURCE_DIR "/scenes/room-4lights.json";

/// Names in `dir` that a write's temporary has (".NAME.tmp…").
std::vector<std::string> temporaries(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.size() > 1 && name[0] == '.' && name.find(".tmp") != std::string::npos) out.push_back(name);
  }
  return out;
}

bool is_char_device(const fs::path& p) {
  struct stat st {};
  return ::lstat(p.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

/// A small tmpfs mounted at `dir` (root only) and filled to the last byte, or
/// nothing where it cannot be mounted. Unmounted when it goes.
class FullDisk {
public:
  explicit FullDisk(const fs::path& dir) : m_dir(dir) {
    if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=256k") != 0) return;
    m_mounted = true;
    const int fd = ::open((dir / "filler").c_str(), O_WRONLY | O_CREAT, 0600);
    const std::string block(4096, 'x');
    while (::write(fd, block.data(), block.size()) > 0) {
    }
    while (::write(fd, block.data(), 1) > 0) {
    }
    ::close(fd);
  }
  ~FullDisk() {
    if (m_mounted) ::umount2(m_dir.c_str(), MNT_DETACH);
  }
  bool mounted() const { return m_mounted; }

private:
  fs::path m_dir;
  bool m_mounted = false;
};

/// The contract for a failed write: one line naming `file` with the system's reason, a non-zero exit that is not a crash.
void check_write_failed(const test::RunResult& r, const fs::path& file, const std::string& reason) {
  CAPTURE(r.exit_code, r.err);
  CHECK(r.exit_code == 2);
  CHECK(test::line_count(r.err) == 1);
  CHECK_THAT(r.err, Contains(file.string()));
  CHECK_THAT(r.err, Contains(reason));
  CHECK_THAT(r.err, !Contains("internal error"));
}

} // namespace

TEST_CASE("a symlink planted at a temporary's name is not followed, and one at the target is replaced", "[output][security]") {
  const auto dir = test::output_dir("output_planted_symlink");
  const auto victim = dir / "victim.txt";
  test::write_text(victim, "precious");
  // The names the temporary had before: ".NAME.tmp<pid>.EXT", and without the extension.
  const std::string pid = std::to_string(::getpid());
  for (const std::string& name : {".out.json.tmp" + pid + ".json", ".out.json.tmp" + pid}) fs::create_symlink(victim, dir / name);
  write_atomically(dir / "out.json", std::string("{}\n"));
  CHECK(test::read_file(victim) == "precious");
  CHECK(fs::is_regular_file(fs::symlink_status(dir / "out.json")));
  CHECK(test::read_file(dir / "out.json") == "{}\n");
  // The target itself a link: replaced by the file, the link's target untouched.
  fs::create_symlink(victim, dir / "linked.json");
  write_atomically(dir / "linked.json", std::string("[]\n"));
  CHECK(test::read_file(victim) == "precious");
  CHECK(fs::is_regular_file(fs::symlink_status(dir / "linked.json")));
  // The temporaries are private until renamed, and the file gets the usual permissions.
  CHECK((fs::status(dir / "out.json").permissions() & fs::perms::owner_read) != fs::perms::none);
}

TEST_CASE("a device or FIFO output is written in place, never replaced by a file", "[output]") {
  const auto dir = test::output_dir("output_devices");
  write_atomically("/dev/null", std::string("nothing\n"));
  CHECK(is_char_device("/dev/null"));
  // A null device made where the output goes (mknod needs root).
  const auto node = dir / "report.json";
  if (::mknod(node.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0) {
    const auto r = test::run_hilight({"target", "workplane", kRoom, "--region", "0", "--lux", "300", "-o", node.string()});
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(is_char_device(node));
  }
  // A FIFO: its reader gets the bytes, and it stays a FIFO.
  const auto fifo = dir / "out.fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string received;
  std::thread reader([&] { received = test::read_file(fifo); });
  write_atomically(fifo, std::string("through the pipe\n"));
  reader.join();
  CHECK(received == "through the pipe\n");
  struct stat st {};
  CHECK((::lstat(fifo.c_str(), &st) == 0 && S_ISFIFO(st.st_mode)));
  CHECK(temporaries(dir).empty());
  // /dev/stdout: the bytes on standard output.
  const auto out = test::run_hilight({"target", "workplane", kRoom, "--region", "0", "--lux", "300", "-o", "/dev/stdout"});
  INFO(out.err);
  CHECK(out.exit_code == 0);
  CHECK_THAT(out.out, Contains("illuminance_criteria"));
  // A link to a FIFO outside /dev (planted where the output goes) is
  // replaced, not written through; another user's FIFO is refused.
  const auto planted = dir / "planted.fifo";
  REQUIRE(::mkfifo(planted.c_str(), 0666) == 0);
  fs::create_symlink(planted, dir / "linked.json");
  write_atomically(dir / "linked.json", std::string("{}\n"));
  CHECK(fs::is_regular_file(fs::symlink_status(dir / "linked.json")));
  if (::chown(planted.c_str(), 65534, 65534) == 0 && ::geteuid() != 65534)
    CHECK_THROWS_WITH(write_atomically(planted, std::string("secret")), Contains("another user's"));
  // A new regular file in /dev/shm (a tmpfs under /dev) is an ordinary output.
  if (fs::is_directory("/dev/shm")) {
    const fs::path shm = "/dev/shm/hilight-test-" + std::to_string(::getpid()) + ".json";
    write_atomically(shm, std::string("{}\n"));
    CHECK(test::read_file(shm) == "{}\n");
    fs::remove(shm);
  }
  // A block device is refused.
  if (fs::exists("/dev/loop0") && fs::is_block_file("/dev/loop0"))
    CHECK_THROWS_WITH(write_atomically("/dev/loop0", std::string("x")), Contains("block device"));
}

TEST_CASE("a failed write is one error naming the file, and nothing under its name", "[output]") {
  const auto dir = test::output_dir("output_write_fails");
  // A file size limit makes write() fail part way, as a full disk does.
  struct rlimit old {};
  ::getrlimit(RLIMIT_FSIZE, &old);
  const auto previous = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit small = {4096, old.rlim_max};
  REQUIRE(::setrlimit(RLIMIT_FSIZE, &small) == 0);
  std::string message;
  try {
    write_atomically(dir / "big.json", std::string(100000, 'x'));
  } catch (const hilight::InputError& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, previous);
  CHECK_THAT(message, Contains((dir / "big.json").string()));
  CHECK_THAT(message, Contains("File too large"));
  CHECK_FALSE(fs::exists(dir / "big.json"));
  CHECK(temporaries(dir).empty());
  // Straight to a device that is always full.
  CHECK_THROWS_WITH(write_atomically("/dev/full", std::string("x")), Contains("/dev/full") && Contains("No space left on device"));
  const auto r = test::run_hilight({"target", "workplane", kRoom, "--region", "0", "--lux", "300", "-o", "/dev/full"});
  check_write_failed(r, "/dev/full", "No space left on device");
}

TEST_CASE("on a full disk solve -o, --report, target workplane -o, the glTF writers and EXR fail cleanly", "[output][cli]") {
  const auto dir = test::output_dir("output_full_disk");
  const auto target = dir / "target.ply";
  REQUIRE(test::run_hilight({"render", kRoom, "--lights", kRoomLights, "-o", target.string(), "--max-edge", "0.6", "--bounces", "0"})
              .exit_code == 0);
  const auto full = dir / "full";
  fs::create_directories(full);
  const FullDisk disk(full);
  if (!disk.mounted()) {
    std::printf("SKIPPED: cannot mount a tmpfs here (needs root)\n");
    return;
  }
  const std::vector<std::string> solve = {"solve", kRoom, "--target", target.string(), "--max-edge", "0.6", "--bounces", "0",
                                          "--lights", "1", "--cache", "none", "--evaluation-points", "2000"};
  auto with = [](std::vector<std::string> args, const std::vector<std::string>& extra) {
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  check_write_failed(test::run_hilight(with(solve, {"-o", (full / "one.json").string()})), full / "one.json", "No space left on device");
  check_write_failed(test::run_hilight(with(solve, {"-o", (dir / "lights.json").string(), "--report", (full / "report.json").string()})),
                     full / "report.json", "No space left on device");
  check_write_failed(test::run_hilight({"target", "workplane", kRoom, "--region", "0", "--lux", "300", "-o", (full / "desks.json").string()}),
                     full / "desks.json", "No space left on device");
  for (const std::string name : {"scene.glb", "scene.gltf"})
    check_write_failed(test::run_hilight({"export", kRoom, "--lights", kRoomLights, "-o", (full / name).string()}), full / name,
                       "No space left on device");
  // The EXR error named the temporary file; it names the target.
  const auto exr = test::run_hilight({"render", kRoom, "--lights", kRoomLights, "-o", (full / "image.exr").string(), "--bounces", "0",
                                      "--width", "64", "--height", "48", "--max-edge", "0.6"});
  check_write_failed(exr, full / "image.exr", "No space left on device");
  CHECK_THAT(exr.err, !Contains(".tmp"));
  for (const std::string name : {"one.json", "report.json", "desks.json", "scene.glb", "scene.gltf", "image.exr"}) {
    INFO(name);
    CHECK_FALSE(fs::exists(full / name));
  }
  CHECK(temporaries(full).empty());
}

TEST_CASE("a luminaire leaves as glTF, its IES file named in the extras (it was refused without naming the file)", "[output][cli]") {
  const auto dir = test::output_dir("output_gltf_luminaire");
  test::write_text(dir / "panel.ies", test::linear_ies());
  test::write_text(dir / "lights.json",
                   R"({"lights":[{"type":"luminaire","profile":"panel.ies","position":[2,2.5,2],"dimming":1}]})");
  const auto out = dir / "scene.glb";
  const auto r = test::run_hilight({"export", kRoom, "--lights", (dir / "lights.json").string(), "-o", out.string()});
  CAPTURE(r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(fs::exists(out));
  std::ifstream in(out, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK_THAT(bytes, Contains("panel.ies"));
  CHECK(temporaries(dir).empty());
}

// A library planted in the folder where a user runs hilight (issue 35),
// copied there under the names of the libraries hilight needs. Were it
// loaded, its constructor would leave a file named "planted-library-ran".
#include <fcntl.h>
#include <unistd.h>

__attribute__((constructor)) static void planted_library_ran() {
  const int fd = ::open("planted-library-ran", O_WRONLY | O_CREAT, 0644);
  if (fd >= 0) ::close(fd);
}

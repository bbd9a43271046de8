// One writer per output folder; see folder_lock.hpp.
#include "io/folder_lock.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>
#include <string>

namespace dilatant {
namespace {

// What the file says of its holder, on one line.
std::string holder_of(int fd) {
  std::string text(256, '\0');
  const ssize_t n = ::pread(fd, text.data(), text.size(), 0);
  text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  if (const auto end = text.find('\n'); end != std::string::npos) text.resize(end);
  return text;
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", &utc);
  return text;
}

}  // namespace

FolderLock::FolderLock(const std::filesystem::path& folder, std::string_view what) {
  const std::filesystem::path file = folder / kFolderLockName;
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return;  // the folder was checked writable; a file system that says no: unlocked
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    if (error == EWOULDBLOCK) {
      const std::string holder = holder_of(fd);
      ::close(fd);
      throw FolderInUse(fmt::format("{}: in use by another dilatant ({}); wait for it or stop it",
                                    folder.string(), holder.empty() ? "its lock is held" : holder));
    }
    ::close(fd);  // no flock on this file system (ENOLCK, EINVAL, ...): unlocked, as before
    return;
  }
  fd_ = fd;
  const std::string text = fmt::format("pid {}, {}, since {} UTC\n", ::getpid(), what, utc_now());
  if (::ftruncate(fd_, 0) == 0) {
    // Informative only: a short write leaves a shorter description, nothing else.
    [[maybe_unused]] const ssize_t written = ::pwrite(fd_, text.data(), text.size(), 0);
  }
}

FolderLock::FolderLock(FolderLock&& other) noexcept : fd_(other.fd_) { other.fd_ = -1; }

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  // Emptied before the lock goes, so a description is only ever a live holder's.
  [[maybe_unused]] const int emptied = ::ftruncate(fd_, 0);
  ::close(fd_);
}

}  // namespace dilatant

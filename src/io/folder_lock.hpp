#pragma once
// One writer per output folder. A run resumes from the checkpoint in its
// folder and a sweep skips the points its folder says are done, so two
// processes given the same --out (a sweep started again while the first still
// runs in the background, a pinned binary and the current one on one study)
// would each compute the same points and overwrite each other's checkpoints
// and tables, the files whole (each is written then renamed) but the work
// doubled and, with different binaries or thread counts, the histories mixed.
//
// The lock is flock(2) on FOLDER/.dilatant.lock, held for the writer's life:
// the kernel releases it when the process ends however it ends, so a killed
// run leaves no stale lock. The second writer is refused as bad input (exit 2;
// in Python a BlockingIOError) in one line naming the folder and the holder:
//     out/a: in use by another dilatant (pid 4242, a sweep, since
//     2026-11-29 06:40:12 UTC); wait for it or stop it
// The file holds the holder's description for the next one to read, and is
// emptied when the lock is released (an empty lock file means nothing). Locks
// are per open file, so two writers in one process (two Python runs on one
// folder) are refused too. On a file system without flock (some cluster file
// systems answer ENOLCK or EINVAL) the folder is used unlocked, as before.
#include <cerrno>
#include <filesystem>
#include <string>
#include <string_view>

#include "io/output_folder.hpp"

namespace dilatant {

inline constexpr std::string_view kFolderLockName = ".dilatant.lock";

// An OutputFolderError with EWOULDBLOCK: bad input to the CLI (exit 2), and
// in Python the OSError subclass of that errno, BlockingIOError.
struct FolderInUse : OutputFolderError {
  explicit FolderInUse(const std::string& message) : OutputFolderError(message, EWOULDBLOCK) {}
};

class FolderLock {
 public:
  // Takes the lock of `folder` (which must exist) for `what` (e.g. "a
  // sweep"); throws FolderInUse when another holder has it.
  FolderLock(const std::filesystem::path& folder, std::string_view what);
  ~FolderLock();
  FolderLock(FolderLock&& other) noexcept;
  FolderLock& operator=(FolderLock&&) = delete;
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  bool held() const { return fd_ >= 0; }  // false where the file system has no flock

 private:
  int fd_ = -1;
};

}  // namespace dilatant

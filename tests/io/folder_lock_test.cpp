// One writer per output folder (io/folder_lock.hpp): a second lock on a held
// folder is refused, naming the folder and the holder; a released lock leaves
// an empty file and can be taken again; the lock is the kernel's, so a second
// process is refused too (tests/app/folder_in_use_test.cpp).
#include "io/folder_lock.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <optional>
#include <string>

#include "io/io_test_files.hpp"

namespace dilatant::io::folder_lock_test {
namespace {

namespace fs = std::filesystem;

std::string refusal(const fs::path& folder) {
  try {
    const FolderLock second(folder, "a second");
  } catch (const FolderInUse& e) {
    return e.what();
  }
  return "";
}

TEST(FolderLock, ASecondLockOnAHeldFolderIsRefusedNamingTheHolder) {
  test::TempDir dir;
  const FolderLock first(dir.path(), "a sweep");
  ASSERT_TRUE(first.held());
  const std::string message = refusal(dir.path());
  // "<folder>: in use by another dilatant (pid N, a sweep, since <UTC time>); ..."
  const std::string start = fmt::format("{}: in use by another dilatant (pid {}, a sweep, since ",
                                        dir.path().string(), ::getpid());
  EXPECT_EQ(message.substr(0, start.size()), start) << message;
  EXPECT_NE(message.find(" UTC); wait for it or stop it"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
}

TEST(FolderLock, AReleasedLockLeavesAnEmptyFileAndIsTakenAgain) {
  test::TempDir dir;
  std::optional<FolderLock> first;
  first.emplace(dir.path(), "a shear-cell run");
  EXPECT_GT(fs::file_size(dir.path() / kFolderLockName), 0u);
  first.reset();
  EXPECT_EQ(fs::file_size(dir.path() / kFolderLockName), 0u);
  EXPECT_EQ(refusal(dir.path()), "");  // free again: the second takes it
}

TEST(FolderLock, AMovedLockIsStillHeldOnce) {
  test::TempDir dir;
  FolderLock first(dir.path(), "a sweep");
  const FolderLock moved(std::move(first));
  EXPECT_TRUE(moved.held());
  EXPECT_FALSE(first.held());  // NOLINT(bugprone-use-after-move): the moved-from state
  EXPECT_NE(refusal(dir.path()), "");
}

TEST(FolderLock, TwoFoldersAreIndependent) {
  test::TempDir dir;
  fs::create_directories(dir.path() / "a");
  fs::create_directories(dir.path() / "b");
  const FolderLock a(dir.path() / "a", "a sweep");
  EXPECT_EQ(refusal(dir.path() / "b"), "");
}

}  // namespace
}  // namespace dilatant::io::folder_lock_test

// The output folder (issue 31, item 7): a file in its place or a parent that
// is a file is an OutputFolderError naming the folder, with the errno Python
// maps to FileExistsError or NotADirectoryError; a fresh run's clean-up
// removes the files a run owns and nothing else.
#include "io/output_folder.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>

#include "io/io_test_files.hpp"

namespace dilatant::io::output_folder_test {
namespace {

namespace fs = std::filesystem;

int error_of(const fs::path& folder, std::string& message) {
  try {
    prepare_output_folder(folder);
  } catch (const OutputFolderError& e) {
    message = e.what();
    return e.error_number();
  }
  return 0;
}

TEST(OutputFolder, CreatesMissingParents) {
  test::TempDir dir;
  prepare_output_folder(dir.path() / "a" / "b");
  EXPECT_TRUE(fs::is_directory(dir.path() / "a" / "b"));
  prepare_output_folder(dir.path() / "a" / "b");  // an existing folder is fine
}

TEST(OutputFolder, AFileInItsPlaceIsFileExists) {
  test::TempDir dir;
  const auto file = dir.write("out", "not a folder\n");
  std::string message;
  EXPECT_EQ(error_of(file, message), EEXIST);
  EXPECT_EQ(message, file.string() + ": cannot use as the output folder: a file is there (" +
                         std::strerror(EEXIST) + ")");
}

TEST(OutputFolder, AFileAsItsParentIsNotADirectory) {
  test::TempDir dir;
  const auto file = dir.write("parent", "not a folder\n");
  std::string message;
  EXPECT_EQ(error_of(file / "out", message), ENOTDIR);
  EXPECT_NE(message.find((file / "out").string() + ": cannot create the output folder"),
            std::string::npos)
      << message;
}

TEST(OutputFolder, CleaningRemovesOwnedFilesOnly) {
  test::TempDir dir;
  for (const char* name : {"summary.json", "cell.pvd", "notes.txt", "snapshots/particles_0000.vtp",
                           "snapshots/contacts_0000.vtp", "other/particles_0000.vtp"})
    dir.write(name, "x");
  dir.write("kept/particles_0001.vtp", "x");
  remove_earlier_results(dir.path(), {"summary.json", "cell.pvd", "timeseries.csv"},
                         {{"snapshots", {"particles_", "contacts_"}}, {"kept", {"contacts_"}}});
  EXPECT_FALSE(fs::exists(dir.path() / "summary.json"));
  EXPECT_FALSE(fs::exists(dir.path() / "cell.pvd"));
  EXPECT_FALSE(fs::exists(dir.path() / "snapshots"));
  EXPECT_TRUE(fs::exists(dir.path() / "notes.txt"));
  EXPECT_TRUE(fs::exists(dir.path() / "other/particles_0000.vtp"));
  EXPECT_TRUE(fs::exists(dir.path() / "kept/particles_0001.vtp"));
}

}  // namespace
}  // namespace dilatant::io::output_folder_test

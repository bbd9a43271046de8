#pragma once
// The folder a run, sweep or analysis writes its results to (--out), and what
// a fresh run does with an earlier run's files there (docs/shear-cell.md,
// "The output folder").
//
// A folder that cannot be used is bad input (exit 2), in one line naming the
// folder and the cause:
//     out/a: cannot use as the output folder: a file is there (File exists)
//     out/a: cannot write in the output folder (Permission denied)
// Its errno (EEXIST, ENOTDIR, EACCES, EROFS, ...) goes with it, so that Python
// raises the built-in OSError subclass os.makedirs would (FileExistsError,
// NotADirectoryError, PermissionError, OSError).
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

#include "io/input_error.hpp"

namespace dilatant {

struct OutputFolderError : InputError {
  OutputFolderError(const std::string& message, int error) : InputError(message), errno_(error) {}
  int error_number() const { return errno_; }

 private:
  int errno_;
};

// Creates `folder` and its missing parents, and checks that files can be
// created in it; throws OutputFolderError when not.
void prepare_output_folder(const std::filesystem::path& folder);

// For --resume: `folder` must hold checkpoint.bin, or a typo in --out would
// silently cost a run from scratch; InputError naming the folder when not.
void require_checkpoint_to_resume(const std::filesystem::path& folder);

// Removes from `folder` the files an earlier run left there that this run
// would write too: the plain files named in `files`, and in each folder of
// `series` (a folder name, then the prefixes of its numbered files, e.g.
// {"snapshots", "particles_", "contacts_"}) those files, then the folder if
// nothing else is left in it. Files not named are never touched.
struct OwnedSeries {
  std::string_view folder;
  std::initializer_list<std::string_view> prefixes;
};
void remove_earlier_results(const std::filesystem::path& folder,
                            std::initializer_list<std::string_view> files,
                            std::initializer_list<OwnedSeries> series = {});

}  // namespace dilatant

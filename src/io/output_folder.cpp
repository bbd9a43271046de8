// The output folder; see output_folder.hpp.
#include "io/output_folder.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace dilatant {
namespace {

[[noreturn]] void refuse(const std::filesystem::path& folder, std::string_view what, int error) {
  throw OutputFolderError(fmt::format("{}: {} ({})", folder.string(), what, std::strerror(error)),
                          error);
}

}  // namespace

void require_checkpoint_to_resume(const std::filesystem::path& folder) {
  if (!std::filesystem::exists(folder / "checkpoint.bin"))
    throw InputError(folder.string() +
                     ": --resume found no checkpoint.bin there; check --out, or run without "
                     "--resume to start anew");
}

void prepare_output_folder(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(folder, ec);
  if (fs::exists(status) && !fs::is_directory(status))
    refuse(folder, "cannot use as the output folder: a file is there", EEXIST);
  fs::create_directories(folder, ec);
  if (ec) refuse(folder, "cannot create the output folder", ec.value());
  // access() answers for the real user, as the kernel will when the run
  // writes; a read-only file system answers EROFS.
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    refuse(folder, "cannot write in the output folder", errno);
}

void remove_earlier_results(const std::filesystem::path& folder,
                            std::initializer_list<std::string_view> files,
                            std::initializer_list<OwnedSeries> series) {
  namespace fs = std::filesystem;
  for (const auto name : files) {
    const fs::path file = folder / name;
    if (fs::is_regular_file(fs::symlink_status(file))) fs::remove(file);
  }
  for (const auto& s : series) {
    const fs::path dir = folder / s.folder;
    if (!fs::is_directory(fs::symlink_status(dir))) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      for (const auto prefix : s.prefixes)
        if (name.starts_with(prefix) && entry.is_regular_file()) fs::remove(entry.path());
    }
    if (fs::is_empty(dir)) fs::remove(dir);
  }
}

}  // namespace dilatant

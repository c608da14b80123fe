#pragma once
// The run's output folder. Nothing in it is ever half-written under its final name: every file is
// written under a temporary name beside its final name and renamed into place (rename within one
// folder is atomic on POSIX), and run.json is written last, so its presence marks a finished run.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/checkpoint_access.hpp"

namespace heliostand {

class OutputFolderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Where a file is written before it is renamed to `final_path`: a hidden sibling "dir/.name.tmp".
std::filesystem::path temporary_sibling(const std::filesystem::path& final_path);

// "cannot write FINAL_PATH: REASON": the file the user asked for (not its temporary) and the system's reason for
// `reason`, an errno value read right after the failed call, or that the write stopped short where it is 0 (the
// library noticed a short write itself and the system gave no reason).
OutputFolderError cannot_write(const std::filesystem::path& final_path, int reason);

// Writes `contents` as the whole file `path`, or throws cannot_write(`final_path`, ...): `path` is where the bytes go
// (a temporary), `final_path` the name the user will know the file by.
void write_whole_file(const std::filesystem::path& path, std::string_view contents,
                      const std::filesystem::path& final_path);

// Makes `folder` (with its parents) to write into, or finds it there: "cannot create output folder F: REASON" or
// "output folder F exists and is not a folder" (OutputFolderError) otherwise. True when it already holds something,
// which each kind of output folder (a run's, a batch's) then judges by its own marker.
bool make_output_folder(const std::filesystem::path& folder);

// Deletes everything in `folder`, keeping the folder.
void empty_folder(const std::filesystem::path& folder);

// A file under its temporary name until commit() renames it into place. If never committed (an
// exception unwound past it), the temporary is deleted, so no stray temporaries are left behind.
// A name the user gave may be a symbolic link, or a file that is not a regular one (/dev/null, a FIFO): a link is
// followed, so that the file it names is replaced and the link kept, as `>` in a shell would; a device or a FIFO is
// written in place, since a rename would replace the node itself (which root may do: `-o /dev/full` once turned
// /dev/full into a JSON file).
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path final_path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&&) = delete;

  const std::filesystem::path& temporary_path() const { return temporary_; }  // empty where written in place
  const std::filesystem::path& final_path() const { return final_; }
  bool committed() const { return committed_; }
  bool written_in_place() const { return temporary_.empty(); }

  // Writes `contents` as the whole temporary file. If it cannot be written, throws OutputFolderError
  // "cannot write FINAL_PATH: REASON", naming the file the user asked for (not its temporary) and the system's
  // reason, or that the write stopped short where the system gave none; "cannot write FINAL_PATH: it is a folder, not
  // a file" when a folder stands where the file belongs (before anything is written).
  void write(std::string_view contents) const;
  // Tries the file before the work that will fill it, with write()'s errors: its temporary is written empty (and
  // removed with this object); a file written in place is only asked whether it may be written, since opening a FIFO
  // waits for its reader and closing it would end the reader's input before the contents came.
  void try_writing() const;
  void commit();   // rename temporary → final (replacing an older final file); nothing to do where written in place

 private:
  std::filesystem::path final_;        // the name the user knows, in every message
  std::filesystem::path destination_;  // the file replaced: final_, or the file a link at final_ names
  std::filesystem::path temporary_;
  bool committed_ = false;
};

class OutputFolder {
 public:
  // A hidden file written into the folder as soon as it is taken: it lets a later `force` run
  // recognise the folder as an earlier heliostand output and clear it — and refuse to clear anything else.
  static constexpr std::string_view marker_name = ".heliostand-output";

  // Creates `root` (with parents). An existing non-empty folder is refused unless `force`; with
  // `force` its contents are deleted, but only if it carries the marker of an earlier run.
  // `resume`: take over the folder of an interrupted run as it is (it must carry the marker and no run.json).
  OutputFolder(std::filesystem::path root, bool force, bool resume = false);

  const std::filesystem::path& root() const { return root_; }
  std::filesystem::path path_of(const std::filesystem::path& relative) const { return root_ / relative; }

  // Writes `contents` to root/relative through a temporary and records it as an output.
  void write_file(const std::filesystem::path& relative, std::string_view contents);

  // Adds a path (relative to root, '/'-separated) to the list of outputs for run.json; once only.
  void record_output(const std::filesystem::path& relative);
  const std::vector<std::string>& output_files() const { return outputs_; }

  // Deletes every temporary (".name.tmp", io/output_folder.hpp) under the folder but those in `keep`: what a
  // killed run was writing. A resumed run starts from its checkpoint and writes them again.
  void remove_stray_temporaries(const std::vector<std::filesystem::path>& keep);

 private:
  friend struct checkpoint::Access;
  void take_over_for_resume();

  std::filesystem::path root_;
  std::vector<std::string> outputs_;
};

}  // namespace heliostand

#pragma once
// A run's output files, published together. They are written into a staging folder and appear in
// the output folder in one atomic step, so an interrupted run leaves the folder as it was and a
// reader never finds a new placements.csv beside an old report.
//
// Publishing (the output folder locked with io/folder_lock.h, so that runs take turns):
// - no folder yet: the staging folder (beside where it will be) is renamed to it;
// - otherwise the staging folder is completed into the whole new folder (the new set, plus every
//   entry of the user's: files hard-linked, folders and what cannot be linked moved and recorded
//   in the manifest) and swapped with the old folder in one renameat2(RENAME_EXCHANGE). The old
//   folder, now at the staging path, is emptied only of what is proven ours (the previous set, the
//   second links of the user's files); anything else goes back, and nothing unproven is deleted;
// - when the staging folder cannot sit beside the output folder (its parent is not writable, or is
//   another filesystem) or the filesystem cannot swap folders, the files are renamed in one at a
//   time after the manifest naming both sets, so a run killed midway leaves files all proven ours,
//   and the next run finishes the publish before its own.
// A symbolic link given as the output folder stays a link: the set is published where it points.
//
// Which files are a previous run's: those its manifest (io/set_manifest.h) lists that are regular
// files. A file the program did not write is the user's even when it bears an output's name: it is
// never removed, and a run that would replace it is refused before any work. A folder written
// before manifests existed counts every known name in it as the program's when it holds a
// report.json that Paver wrote (a JSON object with `design` and `quality_after`).
//
// Recovery: a staging folder is ours only when its name ends in a token that a manifest in it (or
// the output folder's, once swapped) bears. A run publishing into a folder first finishes or undoes
// what a killed run left there; the user's folders of similar names are never touched.
#include <filesystem>
#include <string>
#include <vector>

namespace paver {

class OutputSet {
public:
  // `folder`: the output folder. `known_names`: every file name a run may write there. Creates the
  // staging folder; throws InputError naming the output folder when it cannot.
  OutputSet(std::filesystem::path folder, std::vector<std::string> known_names);
  ~OutputSet();  // unless published, removes the staging folder (what this run wrote in it)
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Where to write the files, under their final names.
  const std::filesystem::path& staging() const { return staging_; }

  // `message` with the staging folder's path replaced by the output folder's: a file that could
  // not be written is named where the user will look for it.
  std::string with_final_names(std::string message) const;

  // Publishes the staged files as described above; `last` goes in after the others when files
  // are moved one at a time. Throws InputError (the output folder as it was) when a file of the
  // user's appeared under one of the set's names during the run.
  void publish(const std::string& last = "report.json");

  // What the publish could not tidy (a previous file that could not be removed, say): one line each.
  const std::vector<std::string>& warnings() const { return warnings_; }

  // Throws InputError, naming the file, when one of `outputs` exists in `folder` and no earlier run
  // wrote it (see above), or when the folder's manifest is not a regular file. For the checks
  // before any work.
  static void refuse_replacing_users_files(const std::filesystem::path& folder,
                                           const std::vector<std::filesystem::path>& outputs,
                                           const std::vector<std::string>& known_names);

  // Finishes or undoes the publishes of killed runs into `folder` (see above), with the folder
  // locked. Returns how many staging folders were dealt with. Publish calls it; public for tests.
  static int recover_interrupted(const std::filesystem::path& folder, const std::vector<std::string>& known_names);

  // For the fault-injection tests: `step` is called before each change a publish or a recovery
  // makes on disk ("exchange", "link notes.txt", ...) and may end the process there;
  // `one_at_a_time` takes the path of a folder whose parent is not writable.
  using StepHook = void (*)(const std::string& step);
  struct TestHooks {
    StepHook step = nullptr;
    bool one_at_a_time = false;
  };
  static void set_test_hooks(TestHooks hooks);

private:
  void publish_by_exchange(const std::vector<std::string>& staged);
  void publish_one_by_one(const std::vector<std::string>& staged, const std::string& last);

  std::filesystem::path shown_;    // the output folder as the user named it
  std::filesystem::path folder_;   // where it is (a symbolic link's target)
  std::filesystem::path staging_;
  std::string token_;
  bool beside_ = false;  // the staging folder is beside the output folder, not in it
  std::vector<std::string> known_;
  std::vector<std::string> warnings_;
  bool published_ = false;
};

}  // namespace paver

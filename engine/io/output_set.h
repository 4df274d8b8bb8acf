#pragma once
// A run's output files, published together. They are written into a staging folder beside the
// output folder and moved in only when every one is complete, so an interrupted run leaves the
// output folder as it was, and a reader never finds a new placements.csv beside an old report.
//
// Publishing: when the output folder does not exist it is the staging folder renamed (atomic);
// when it holds nothing but files of a previous run's set, the two folders are swapped in one
// atomic rename (renameat2 RENAME_EXCHANGE) and the old set removed; when it also holds files of
// the user's, the staged files are renamed in one by one (each atomic, report.json last) and the
// previous run's files that this run did not write are removed, so the set is never mixed.
//
// Which files are a previous run's: those its manifest (`.paver-files`, one name a line, published
// with the set) lists. A file the program did not write is the user's even when it bears an
// output's name: it is never removed, and a run that would replace it is refused before any work.
// A folder written before manifests existed counts every known name in it as the program's when it
// holds a report.json that Paver wrote (a JSON object with `design` and `quality_after`), what
// those versions did; any other report.json is the user's like the rest.
#include <filesystem>
#include <string>
#include <vector>

namespace paver {

class OutputSet {
public:
  // `folder`: the output folder. `known_names`: every file name a run may write there (a
  // previous run's files among them are replaced or removed; any other file is the user's and
  // is left alone). Creates the staging folder; throws InputError naming it when it cannot.
  OutputSet(std::filesystem::path folder, std::vector<std::string> known_names);
  ~OutputSet();  // removes the staging folder and whatever is in it unless published
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Where to write the files, under their final names.
  const std::filesystem::path& staging() const { return staging_; }

  // `message` with the staging folder's path replaced by the output folder's: a file that could
  // not be written is named where the user will look for it.
  std::string with_final_names(std::string message) const;

  // Moves the staged files into the output folder as described above; `last` (if staged) goes in
  // after all the others.
  void publish(const std::string& last = "report.json");

  // Throws InputError, naming the file, when one of `outputs` exists in `folder` and no earlier run
  // wrote it (see above); `known_names` as for the constructor. For the checks before any work.
  static void refuse_replacing_users_files(const std::filesystem::path& folder,
                                           const std::vector<std::filesystem::path>& outputs,
                                           const std::vector<std::string>& known_names);

  // Staging folders left by runs that were killed (their process is gone), beside or inside
  // `folder`; removed quietly. Returns how many.
  static int remove_stale_staging(const std::filesystem::path& folder);

private:
  std::filesystem::path folder_, staging_;
  std::vector<std::string> known_;
  std::vector<std::string> previous_;  // the previous run's files in the folder (see above)
  bool published_ = false;
};

}  // namespace paver

#pragma once
// The output folder DIR of one run (README "Output files"): always exactly one run's
// complete output, whatever runs, fails, is killed or writes into the same DIR at once.
//
//   1. The run writes into a staging folder of its own beside DIR,
//      ".<DIR name>.staging.<pid>-<nonce>", which holds the marker file .gearhb_run
//      (locked with flock for as long as the run lives).
//   2. On success it publishes the staging folder as DIR in one step: a rename onto a
//      DIR that does not exist, or a swap with the old DIR (Linux renameat2
//      RENAME_EXCHANGE); the old output, now in the staging folder's place, is removed.
//      Two runs publishing into one DIR both succeed, each whole: the last one wins.
//   3. On failure (or when the run object goes out of scope unpublished) the staging
//      folder is removed and DIR is left as it was.
//
// Making a staging folder, cleaning abandoned ones and publishing happen under one lock,
// the file ".<DIR name>.lock" beside DIR (flock), so a staging folder is abandoned
// exactly when no process holds the lock of its marker: the owner was killed. Such
// folders are removed by the next run into the same DIR; a live run's never are.
//
// Because DIR is replaced whole it must be new, empty or an earlier run's output, which
// is recognised by the marker: a regular file .gearhb_run whose first line is
// marker_line(). Anything else (a user's folder, a folder merely holding a file or a
// folder named key_numbers.json) is refused with UsageError before anything is written.
#include <filesystem>
#include <string>

namespace gearhb {

class OutputFolder {
 public:
  // The marker file's name and its first line.
  static const char* marker_name() { return ".gearhb_run"; }
  static const char* marker_line() { return "gearhb run output: a new gearhb run into this folder replaces it whole"; }

  // `out` as the user wrote it (--out), `program` the program's name (in the marker).
  // Checks that DIR may be replaced, removes abandoned staging folders and makes this
  // run's own. Throws UsageError naming --out when DIR is not replaceable or not writable.
  OutputFolder(const std::string& out, const std::string& program);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::filesystem::path& staging() const { return staging_; }
  // Publish the staging folder as DIR (step 2). Throws std::runtime_error on I/O failure.
  void publish();

 private:
  std::filesystem::path folder_, staging_;
  std::string out_;
  int marker_fd_ = -1;
  bool published_ = false;
};

}  // namespace gearhb

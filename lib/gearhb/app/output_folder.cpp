#include "gearhb/app/output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <stdexcept>

#include "gearhb/app/cli.hpp"   // UsageError

namespace gearhb {

namespace fs = std::filesystem;

namespace {

// The output folder as an absolute, normalised path without a trailing separator.
fs::path output_folder(const std::string& out) {
  fs::path abs = fs::absolute(out).lexically_normal();
  if (abs.filename().empty()) abs = abs.parent_path();
  if (abs.filename().empty() || abs == abs.root_path() || abs.filename() == "." || abs.filename() == "..")
    throw UsageError("--out '" + out + "' does not name a folder");
  return abs;
}

// Names beside DIR: ".<name>.lock", ".<name>.staging.<id>".
fs::path beside(const fs::path& folder, const std::string& what) {
  return folder.parent_path() / ("." + folder.filename().string() + "." + what);
}

std::string staging_prefix(const fs::path& folder) { return "." + folder.filename().string() + ".staging."; }

// The publish lock, held while this object lives: flock on the folder that holds DIR,
// so a run leaves no file behind. Where the file system has no locks on a folder (NFS
// emulates flock with write locks, which need a file open for writing), the lock is the
// file ".<name>.lock" beside DIR instead, which then stays.
class FolderLock {
 public:
  FolderLock(const fs::path& folder, const std::string& out) {
    fd_ = ::open(folder.parent_path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd_ >= 0 && lock()) return;
    if (fd_ >= 0) ::close(fd_);
    const fs::path file = beside(folder, "lock");
    fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd_ < 0 || !lock())
      throw UsageError("--out '" + out + "': cannot lock " + file.string() + " (" + std::strerror(errno) + ")");
  }
  ~FolderLock() { ::close(fd_); }   // closing releases the lock
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
  bool lock() const {
    while (::flock(fd_, LOCK_EX) != 0)
      if (errno != EINTR) return false;
    return true;
  }
};

// Whether `folder` holds the marker of a gearhb run: a regular file (not a link, not a
// folder) whose first line is the marker line.
bool holds_marker(const fs::path& folder) {
  const fs::path marker = folder / OutputFolder::marker_name();
  const int fd = ::open(marker.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) return false;
  struct stat st {};
  const std::string line = std::string(OutputFolder::marker_line()) + "\n";
  std::string head(line.size(), '\0');
  const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
  const bool same = regular && ::read(fd, head.data(), head.size()) == ssize_t(head.size()) && head == line;
  ::close(fd);
  return same;
}

// DIR is replaced as a whole by a run, so it must be new, empty or hold an earlier run's
// output (its marker): a user's folder of other files is never swept away.
void check_replaceable(const fs::path& folder, const std::string& out) {
  std::error_code ec;
  const auto status = fs::symlink_status(folder, ec);
  if (ec || status.type() == fs::file_type::not_found) return;
  if (status.type() != fs::file_type::directory) throw UsageError("--out '" + out + "' is not a folder");
  if (!fs::is_empty(folder, ec) && !holds_marker(folder))
    throw UsageError("--out '" + out + "' holds files that are not a gearhb run's output (no " +
                     OutputFolder::marker_name() + " marker): choose an empty or new folder");
}

// A staging folder (or a publish's ".old" left by a kill) whose owner is gone: no process
// holds the lock of its marker. Called under the folder lock, so no staging folder is
// between its creation and its lock.
bool abandoned(const fs::path& staging) {
  const int fd = ::open((staging / OutputFolder::marker_name()).c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) return errno == ENOENT;   // no marker: killed while the folder was made
  const bool free = ::flock(fd, LOCK_EX | LOCK_NB) == 0;
  ::close(fd);
  return free;
}

void remove_abandoned_staging(const fs::path& folder) {
  const std::string prefix = staging_prefix(folder);
  std::error_code ec;
  for (fs::directory_iterator it(folder.parent_path(), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) == 0 && it->is_directory(ec) && !it->is_symlink(ec) &&
        abandoned(it->path())) {
      std::error_code rm;
      fs::remove_all(it->path(), rm);
    }
  }
}

// ".<name>.staging.<pid>-<nonce>": unique per run even across hosts sharing a file system.
fs::path new_staging_name(const fs::path& folder) {
  std::random_device rd;
  char nonce[32];
  std::snprintf(nonce, sizeof nonce, "%ld-%08x%08x", long(::getpid()), rd(), rd());
  return folder.parent_path() / (staging_prefix(folder) + nonce);
}

// Test hook (tests/publish_atomic.py): GEARHB_PUBLISH_KILL_AT=staged|swapped kills the
// process with SIGKILL at that point of publish(), to show DIR is never half written.
void kill_point(const char* where) {
  const char* at = std::getenv("GEARHB_PUBLISH_KILL_AT");
  if (at != nullptr && std::strcmp(at, where) == 0) std::raise(SIGKILL);
}

void sync_folder(const fs::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

[[noreturn]] void publish_failed(const fs::path& folder, int error) {
  throw std::runtime_error("cannot publish " + folder.string() + ": " + std::strerror(error));
}

}  // namespace

OutputFolder::OutputFolder(const std::string& out, const std::string& program) : out_(out) {
  folder_ = output_folder(out);
  std::error_code ec;
  fs::create_directories(folder_.parent_path(), ec);
  if (ec) throw UsageError("--out '" + out + "': cannot write there (" + ec.message() + ")");
  check_replaceable(folder_, out);   // before the lock, so a refused run writes nothing
  const FolderLock lock(folder_, out);
  check_replaceable(folder_, out);
  remove_abandoned_staging(folder_);
  staging_ = new_staging_name(folder_);
  if (!fs::create_directory(staging_, ec) || ec)
    throw UsageError("--out '" + out + "': cannot write there (" + (ec ? ec.message() : "exists") + ")");
  const fs::path marker = staging_ / marker_name();
  marker_fd_ = ::open(marker.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644);
  const std::string text = std::string(marker_line()) + "\nprogram: " + program + "\n";
  if (marker_fd_ < 0 || ::write(marker_fd_, text.data(), text.size()) != ssize_t(text.size()) ||
      ::flock(marker_fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    if (marker_fd_ >= 0) ::close(marker_fd_);
    fs::remove_all(staging_, ec);
    throw UsageError("--out '" + out + "': cannot write there (" + std::strerror(error) + ")");
  }
}

OutputFolder::~OutputFolder() {
  std::error_code ec;
  if (!published_) fs::remove_all(staging_, ec);
  if (marker_fd_ >= 0) ::close(marker_fd_);
}

// Rename onto a DIR that does not exist, or swap the two folders and remove the old
// output, now in the staging folder's place. Where the file system cannot swap (EINVAL:
// e.g. NFS), DIR is moved aside first, all under the lock; a kill between the renames
// leaves no DIR, never a mixed one, and the ".old" folder is removed by the next run.
void OutputFolder::publish() {
  sync_folder(staging_);
  kill_point("staged");
  {
    const FolderLock lock(folder_, out_);
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(folder_, ec))) {
      if (::rename(staging_.c_str(), folder_.c_str()) != 0) publish_failed(folder_, errno);
    } else if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, folder_.c_str(), RENAME_EXCHANGE) != 0) {
      if (errno != EINVAL && errno != ENOSYS) publish_failed(folder_, errno);
      const fs::path aside = staging_.string() + ".old";
      if (::rename(folder_.c_str(), aside.c_str()) != 0) publish_failed(folder_, errno);
      if (::rename(staging_.c_str(), folder_.c_str()) != 0) {
        const int error = errno;
        ::rename(aside.c_str(), folder_.c_str());   // the old output back in place
        publish_failed(folder_, error);
      }
      ::rename(aside.c_str(), staging_.c_str());
    }
    sync_folder(folder_.parent_path());
  }
  published_ = true;
  kill_point("swapped");
  std::error_code ec;
  fs::remove_all(staging_, ec);   // the previous output
}

}  // namespace gearhb

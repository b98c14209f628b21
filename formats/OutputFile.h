// The one way a command writes an output file (`--stats`, `ladder -o`, `dit -o`, `run --dump`,
// `compile -o`; docs/security.md "Output files"): the file is built in a private temporary
// directory `OUT.XXXXXX` beside OUT (mkdtemp, 0700) and renamed over OUT. OUT may be a new name
// or a regular file it replaces; a symbolic link (followed or not), directory, device, FIFO or
// socket at OUT is refused, so a link planted in a shared directory is never written through,
// and an existing file owned by someone else in a sticky directory is not replaced (rename
// fails). The temporary directory is removed on every exit path: failure, success, and with
// installSignalCleanup() SIGINT, SIGTERM and SIGHUP of ladderjit itself.
#pragma once

#include <atomic>
#include <string>
#include <string_view>

namespace lj::formats {

/// Whether `path` may be replaced by an output file: absent, or a regular file (lstat, so a
/// symbolic link is refused). False with `error` ("'PATH' exists and is not a regular file (a
/// symbolic link); refusing to replace it"). "-" (standard output) passes.
bool outputReplaceable(const std::string &path, std::string &error);

/// outputReplaceable() and, for a real path, a probe that the directory takes a new file (a
/// temporary directory made and removed): for options checked before a long run.
bool checkOutputPath(const std::string &path, std::string &error);

/// One output file in the making.
class OutputFile {
public:
  OutputFile() = default;
  ~OutputFile(); ///< removes the temporary directory and whatever commit() did not move
  OutputFile(const OutputFile &) = delete;
  OutputFile &operator=(const OutputFile &) = delete;

  /// Check `path` (outputReplaceable) and make the private temporary directory beside it.
  bool open(const std::string &path, std::string &error);
  /// Where the content goes: a name inside the private directory (nothing there yet).
  const std::string &tempPath() const { return temp_; }
  /// Write `data` to tempPath() (a new file, mode 0666 less the umask).
  bool write(std::string_view data, std::string &error);
  /// Check `path` again and rename tempPath() over it; the directory is removed either way.
  bool commit(std::string &error);
  /// Remove everything made so far (also done by the destructor).
  void discard();

private:
  std::string path_, dir_, temp_;
};

/// Write `data` to `path` through an OutputFile; "-" writes to standard output. False with
/// `error` ("cannot write 'PATH': ..." or the refusal of outputReplaceable).
bool writeOutputFile(const std::string &path, std::string_view data, std::string &error);

/// For a command that makes temporary files for a while (`compile`): block SIGINT, SIGTERM
/// and SIGHUP in the calling thread (call before any other thread starts, so every thread
/// inherits the mask) and start a thread that waits for them. On one it kills the registered
/// process groups, removes every OutputFile's temporary directory and the registered paths,
/// then dies of the same signal. Idempotent.
void installSignalCleanup();
/// A path (file or directory tree) the signal cleanup removes while registered.
void registerTempPath(const std::string &path);
void unregisterTempPath(const std::string &path);
/// A child process group the signal cleanup kills (SIGKILL) while `*pgid` is > 0.
void registerProcessGroup(const std::atomic<int> *pgid);
void unregisterProcessGroup(const std::atomic<int> *pgid);

} // namespace lj::formats

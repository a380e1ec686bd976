#ifndef xcrack_directory_lock_h
#define xcrack_directory_lock_h

#include <string>

namespace xcrack
{
  /**
   * A lock on an output directory for the life of a run: two runs (or two
   * resumes) writing into one directory would remove or overwrite each
   * other's results. The lock is an advisory lock (flock) on the file
   * `.xcrack.lock` in the directory, which also names its holder; the
   * system releases it when the holder ends in any way, a kill included,
   * so a lock is never stale. Taken by one process (rank 0).
   */
  class DirectoryLock
  {
  public:
    /**
     * Take the lock on @p directory (which exists). If another process
     * holds it, throw an InputError that names @p entry, the directory and
     * the holder (its process id and command line).
     */
    DirectoryLock(const std::string &directory, const std::string &entry);

    /// Release the lock.
    ~DirectoryLock();

    DirectoryLock(const DirectoryLock &) = delete;
    DirectoryLock &
    operator=(const DirectoryLock &) = delete;

  private:
    int fd = -1;
  };
} // namespace xcrack

#endif

#include <xcrack/command_line.h>
#include <xcrack/directory_lock.h>
#include <xcrack/input_error.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <sys/file.h>
#include <unistd.h>
#include <utility>

namespace xcrack
{
  namespace
  {
    /**
     * The directories this process holds, with the descriptor of the lock
     * and the number of holders: a program may run several Simulators
     * into one directory one after the other (the tests do), and a second
     * flock on the file from the same process would refuse the first.
     */
    std::map<std::string, std::pair<int, unsigned int>> &
    held()
    {
      static std::map<std::string, std::pair<int, unsigned int>> locks;
      return locks;
    }
  } // namespace



  DirectoryLock::DirectoryLock(const std::string &directory,
                               const std::string &entry)
  {
    std::error_code   ignored;
    const std::string key =
      std::filesystem::weakly_canonical(directory, ignored).string();
    if (const auto it = held().find(key); it != held().end())
      {
        fd = it->second.first;
        ++it->second.second;
        return;
      }
    const std::string name = directory + "/.xcrack.lock";
    fd = ::open(name.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0)
      throw InputError(entry + " = " + directory + ": cannot create " + name +
                       ": " + std::strerror(errno) + ".");
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
      {
        const int   error = errno;
        std::string holder(4096, '\0');
        const auto  n = ::read(fd, holder.data(), holder.size());
        holder.resize(n > 0 ? n : 0);
        while (!holder.empty() && holder.back() == '\n')
          holder.pop_back();
        ::close(fd);
        fd = -1;
        if (error == EWOULDBLOCK)
          throw InputError(
            entry + " = " + directory + ": another run is writing there (" +
            (holder.empty() ? "its process is unknown" : holder) +
            "). Wait for it to end, stop it, or choose "
            "another directory.");
        throw InputError(entry + " = " + directory + ": cannot lock " + name +
                         ": " + std::strerror(error) + ".");
      }
    // Name the holder for the next one that tries.
    const std::string text =
      "process " + std::to_string(::getpid()) + ": " + command_line() + "\n";
    held()[key] = {fd, 1};
    if (::ftruncate(fd, 0) == 0)
      {
        const auto written = ::write(fd, text.data(), text.size());
        (void)written;
      }
  }



  DirectoryLock::~DirectoryLock()
  {
    for (auto it = held().begin(); it != held().end(); ++it)
      if (it->second.first == fd)
        {
          if (--it->second.second == 0)
            {
              ::close(fd);
              held().erase(it);
            }
          return;
        }
  }
} // namespace xcrack

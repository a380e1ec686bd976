#include <xcrack/output_file.h>

#include <cerrno>
#include <cstring>
#include <ext/stdio_filebuf.h>
#include <fcntl.h>
#include <filesystem>
#include <ostream>
#include <stdexcept>

namespace xcrack
{
  void
  write_file(const std::string                         &path,
             const std::function<void(std::ostream &)> &write)
  {
    const std::string tmp = path + ".tmp";
    // A stale temporary file (a killed run's), or a link planted in its
    // place, goes (a link itself, not its target); the new one is created
    // exclusively and never through a link, so the data cannot land
    // outside the output directory.
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    const int fd = ::open(tmp.c_str(),
                          O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                          0666);
    if (fd < 0)
      throw std::runtime_error("could not create " + tmp + ": " +
                               std::strerror(errno) +
                               " (is another process writing there?).");
    {
      // Closes fd when it goes.
      __gnu_cxx::stdio_filebuf<char> buffer(fd,
                                            std::ios::out | std::ios::binary);
      std::ostream                   out(&buffer);
      write(out);
      out.flush();
      const bool flushed = out.good();
      const bool closed  = (buffer.close() != nullptr);
      if (!flushed || !closed)
        {
          const int error = errno;
          std::filesystem::remove(tmp, ignored);
          throw std::runtime_error("could not write " + path + ": " +
                                   std::strerror(error) +
                                   " (the disk may be full).");
        }
    }
    std::error_code error;
    std::filesystem::rename(tmp, path, error);
    if (error)
      throw std::runtime_error("could not write " + path + ": " +
                               error.message() + ".");
  }
} // namespace xcrack

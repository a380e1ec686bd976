#include <xcrack/output_file.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace xcrack
{
  void
  write_file(const std::string                         &path,
             const std::function<void(std::ostream &)> &write)
  {
    const std::string tmp = path + ".tmp";
    {
      std::ofstream out(tmp, std::ios::binary);
      if (!out)
        throw std::runtime_error("could not open " + tmp +
                                 " for writing: " + std::strerror(errno) + ".");
      write(out);
      out.close();
      if (!out)
        throw std::runtime_error("could not write " + path + ": " +
                                 std::strerror(errno) +
                                 " (the disk may be full).");
    }
    std::error_code error;
    std::filesystem::rename(tmp, path, error);
    if (error)
      throw std::runtime_error("could not write " + path + ": " +
                               error.message() + ".");
  }
} // namespace xcrack

#include <xcrack/command_line.h>

#include <algorithm>
#include <fstream>
#include <iterator>

#ifndef XCRACK_VERSION
#  define XCRACK_VERSION "unknown"
#endif

namespace xcrack
{
  std::string
  command_line()
  {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string   text((std::istreambuf_iterator<char>(in)),
                     std::istreambuf_iterator<char>());
    std::replace(text.begin(), text.end(), '\0', ' ');
    while (!text.empty() && text.back() == ' ')
      text.pop_back();
    return text;
  }



  std::string
  version()
  {
    return XCRACK_VERSION;
  }
} // namespace xcrack

#include <xcrack/command_line.h>
#include <xcrack/output_file.h>
#include <xcrack/run_record.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>

#ifndef XCRACK_VERSION
#  define XCRACK_VERSION "unknown"
#endif

namespace xcrack
{
  namespace
  {
    /// The time now, in ISO 8601 (UTC).
    std::string
    now()
    {
      const std::time_t t =
        std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
      std::ostringstream s;
      s << std::put_time(std::gmtime(&t), "%Y-%m-%dT%H:%M:%SZ");
      return s.str();
    }

    /// The files a run writes into its output directory (but run.json and
    /// the checkpoint).
    const std::regex &
    result_files()
    {
      static const std::regex names(
        "front_.*\\.csv|crack[0-9]*-.*\\.vtu|crack\\.pvd|solution-.*\\.p?vtu|"
        "solution\\.pvd|statistics\\.csv|parameters\\.prm");
      return names;
    }



    /// @p text as a JSON string.
    std::string
    quoted(const std::string &text)
    {
      std::string result = "\"";
      for (const char c : text)
        {
          if (c == '"' || c == '\\')
            result += '\\';
          if (c == '\n')
            result += "\\n";
          else if (static_cast<unsigned char>(c) >= 0x20)
            result += c;
        }
      return result + "\"";
    }
  } // namespace



  RunRecord::RunRecord(const std::string &directory,
                       const MPI_Comm     communicator)
    : directory(directory)
    , root(Utilities::MPI::this_mpi_process(communicator) == 0)
  {}



  void
  RunRecord::start(const bool resumed_run)
  {
    resumed      = resumed_run;
    start_time   = now();
    command_line = xcrack::command_line();
    if (!root)
      return;
    if (resumed)
      {
        // The results this run continues: the files of the earlier
        // processes of the run (the directory held only this run's since
        // it started), so that the record lists every file of the run, not
        // only those the resumed process writes.
        for (const auto &entry : std::filesystem::directory_iterator(directory))
          {
            const std::string name = entry.path().filename().string();
            if ((entry.is_regular_file() &&
                 std::regex_match(name, result_files())) ||
                (entry.is_directory() && name == "checkpoint"))
              files.push_back(name);
          }
        std::sort(files.begin(), files.end());
      }
    else
      {
        // What an earlier run wrote and this one will write anew (its
        // results, run.json, the figures contrib/ drew from them, the
        // checkpoint directories; nothing else of the user's) goes aside
        // into .earlier until this run's first results are written
        // (keep_results()), and comes back if the run stops on bad input
        // before (restore_earlier()). A stale .earlier is that of a run
        // killed in its first solve: its results were replaced.
        const std::regex            figures("growth_.*\\.png|front\\.png");
        const std::regex            checkpoints("checkpoint(\\.tmp|\\.old)?");
        const std::regex            temporary(".*\\.tmp");
        const std::filesystem::path earlier =
          std::filesystem::path(directory) / ".earlier";
        std::filesystem::remove_all(earlier);
        std::filesystem::create_directory(earlier);
        for (const auto &entry : std::filesystem::directory_iterator(directory))
          {
            const std::string name = entry.path().filename().string();
            const bool        file = entry.is_regular_file();
            if (file && std::regex_match(name, temporary))
              std::filesystem::remove(entry.path());
            else if ((file && (std::regex_match(name, result_files()) ||
                               std::regex_match(name, figures) ||
                               name == "run.json")) ||
                     (entry.is_directory() &&
                      std::regex_match(name, checkpoints)))
              std::filesystem::rename(entry.path(), earlier / name);
          }
      }
    write();
  }



  void
  RunRecord::keep_results()
  {
    if (root)
      std::filesystem::remove_all(std::filesystem::path(directory) /
                                  ".earlier");
  }



  void
  RunRecord::restore_earlier()
  {
    const std::filesystem::path earlier =
      std::filesystem::path(directory) / ".earlier";
    if (!root || !std::filesystem::is_directory(earlier))
      return;
    for (const std::string &name : files)
      std::filesystem::remove_all(std::filesystem::path(directory) / name);
    std::filesystem::remove(std::filesystem::path(directory) / "run.json");
    for (const auto &entry : std::filesystem::directory_iterator(earlier))
      std::filesystem::rename(entry.path(),
                              std::filesystem::path(directory) /
                                entry.path().filename());
    std::filesystem::remove_all(earlier);
  }



  void
  RunRecord::add_file(const std::string &name)
  {
    if (root && std::find(files.begin(), files.end(), name) == files.end())
      {
        files.push_back(name);
        write();
      }
  }



  void
  RunRecord::finish(const std::string &final_status,
                    const std::string &final_reason)
  {
    status   = final_status;
    reason   = final_reason;
    end_time = now();
    if (root)
      write();
  }



  void
  RunRecord::write() const
  {
    write_file(directory + "/run.json", [this](std::ostream &out) {
      out << "{\n  \"status\": " << quoted(status)
          << ",\n  \"reason\": " << quoted(reason)
          << ",\n  \"start\": " << quoted(start_time)
          << ",\n  \"end\": " << quoted(end_time)
          << ",\n  \"resumed\": " << (resumed ? "true" : "false")
          << ",\n  \"version\": " << quoted(XCRACK_VERSION)
          << ",\n  \"command\": " << quoted(command_line)
          << ",\n  \"files\": [";
      for (unsigned int i = 0; i < files.size(); ++i)
        out << (i > 0 ? ", " : "") << quoted(files[i]);
      out << "]\n}\n";
    });
  }
} // namespace xcrack

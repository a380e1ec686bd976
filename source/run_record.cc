#include <xcrack/command_line.h>
#include <xcrack/output_file.h>
#include <xcrack/run_record.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

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
        "front_.*\\.csv|crack[0-9]*-.*\\.vtu|crack_mesh[0-9]*-.*\\.vtu|"
        "crack\\.pvd|solution-.*\\.p?vtu|"
        "solution\\.pvd|statistics\\.csv|parameters\\.prm");
      return names;
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
  RunRecord::set_overrides(const std::vector<std::string> &assignments)
  {
    overrides = assignments;
  }



  void
  RunRecord::set_cycles(const double total)
  {
    cycles = total;
  }



  void
  RunRecord::set_unreliable(const std::vector<std::string> &solves,
                            const unsigned long long        n_points,
                            const std::vector<std::string> &reasons,
                            const double                    n_cycles)
  {
    unreliable_solves  = solves;
    unreliable_points  = n_points;
    unreliable_reasons = reasons;
    unreliable_cycles  = n_cycles;
    if (root)
      write();
  }



  void
  RunRecord::write() const
  {
    nlohmann::ordered_json record;
    record["status"]  = status;
    record["reason"]  = reason;
    record["start"]   = start_time;
    record["end"]     = end_time;
    record["resumed"] = resumed;
    record["version"] = xcrack::version();
    record["command"] = command_line;
    if (!overrides.empty())
      record["overrides"] = overrides;
    if (cycles)
      record["cycles"] = *cycles;
    // What the run cannot vouch for: the solves with front points whose K
    // is flagged (their keys, as the files name them), and the cycles that
    // rest on those K's.
    if (!unreliable_solves.empty())
      {
        nlohmann::ordered_json &flagged = record["unreliable"];
        flagged["solves"]               = unreliable_solves;
        flagged["front_points"]         = unreliable_points;
        flagged["reasons"]              = unreliable_reasons;
        if (cycles)
          flagged["cycles"] = unreliable_cycles;
      }
    record["files"] = files;
    // (Invalid UTF-8 in a path or a message is replaced, not thrown.)
    const std::string text =
      record.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
    write_file(directory + "/run.json",
               [&](std::ostream &out) { out << text << '\n'; });
  }
} // namespace xcrack

#ifndef xcrack_run_record_h
#define xcrack_run_record_h

#include <deal.II/base/mpi.h>

#include <string>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * `run.json` in the output directory: what the run is and how far it
   * got, for every reader, a person or a script (contrib/plot_*.py): its
   * status (`running`, then `completed` or `failed`, with the reason), the
   * start and end times, xcrack's version, the command line, and the files
   * it wrote. A run killed on the way leaves `running`: its files are
   * incomplete. Rewritten atomically whenever it changes (rank 0).
   *
   * A new run (not a resumed one) first removes the numbered results of an
   * earlier run in the same directory (front_*.csv, crack*.vtu,
   * solution-*, the .pvd series, statistics.csv, the checkpoint, the
   * figures of contrib/), so that no stale step is taken for one of this
   * run's; other files are left alone. This happens only once the run has
   * passed all its input checks.
   */
  class RunRecord
  {
  public:
    RunRecord(const std::string &directory, const MPI_Comm communicator);

    /// Clear an earlier run's results (unless @p resumed) and record the
    /// start.
    void
    start(const bool resumed);

    /// A file the run wrote (a name in the output directory).
    void
    add_file(const std::string &name);

    /// The end: @p status `completed` or `failed`, and why.
    void
    finish(const std::string &status, const std::string &reason);

  private:
    void
    write() const;

    std::string              directory;
    bool                     root;
    std::string              status = "running", reason;
    std::string              start_time, end_time, command_line;
    bool                     resumed = false;
    std::vector<std::string> files;
  };
} // namespace xcrack

#endif

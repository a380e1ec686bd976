#ifndef xcrack_run_record_h
#define xcrack_run_record_h

#include <deal.II/base/mpi.h>

#include <optional>
#include <string>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * `run.json` in the output directory: what the run is and how far it
   * got, for every reader, a person or a script (contrib/plot_*.py): its
   * status (`running`, then `completed` or `failed`, with the reason), the
   * start and end times, xcrack's version, the command line, the cycles
   * of a growth run, what the run flags as unreliable, and the files it
   * wrote. A run killed on the way leaves `running`: its files are
   * incomplete. Rewritten atomically whenever it changes (rank 0).
   *
   * A new run (not a resumed one) first moves the numbered results of an
   * earlier run in the same directory (front_*.csv, crack*.vtu,
   * solution-*, the .pvd series, statistics.csv, parameters.prm, run.json,
   * the checkpoint, the figures of contrib/) into `.earlier`, so that no
   * stale step is taken for one of this run's; other files are left
   * alone. Once the run's first results are written they go; if an input
   * check of the first solve fails before, they come back. This happens
   * only once the run has passed the input checks of its constructor.
   */
  class RunRecord
  {
  public:
    RunRecord(const std::string &directory, const MPI_Comm communicator);

    /// Clear an earlier run's results (unless @p resumed: then list the
    /// results already there, the run's own) and record the start.
    void
    start(const bool resumed);

    /// The run's first results are written: the earlier run's go.
    void
    keep_results();

    /// The run stopped on bad input before its first results: remove what
    /// it wrote and bring the earlier run's results back.
    void
    restore_earlier();

    /// A file the run wrote (a name in the output directory).
    void
    add_file(const std::string &name);

    /// The entries the command line set (`xcrack -s`), before start().
    void
    set_overrides(const std::vector<std::string> &assignments);

    /// The load cycles a growth run counted.
    void
    set_cycles(const double total);

    /**
     * What the run flags as unreliable: the keys of the solves with
     * flagged front points (`018`), their number, the reasons, and the
     * cycles that rest on their K.
     */
    void
    set_unreliable(const std::vector<std::string> &solves,
                   const unsigned long long        n_points,
                   const std::vector<std::string> &reasons,
                   const double                    n_cycles);

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
    std::vector<std::string> overrides;
    std::optional<double>    cycles;
    std::vector<std::string> unreliable_solves, unreliable_reasons;
    unsigned long long       unreliable_points = 0;
    double                   unreliable_cycles = 0;
  };
} // namespace xcrack

#endif

#ifndef xcrack_run_h
#define xcrack_run_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace xcrack
{
  /// How a run was asked for on the command line.
  struct RunOptions
  {
    /// Continue the run checkpointed in this output directory (`--resume`).
    std::string resume_directory;
    /// The entries set on the command line (`-s`), as given: run.json
    /// records them.
    std::vector<std::string> overrides;
    /// Only check the input (`--check`): build the scene, run every check
    /// the constructor runs, and write no result.
    bool check_only = false;
  };

  /**
   * Run the scene of an already read parameter file: pick the dimension,
   * check every input, then solve and write results. Input errors are
   * thrown as InputError before anything is written.
   */
  void
  run(dealii::ParameterHandler &prm, const RunOptions &options = {});

  /**
   * The checkpoint of the propagation run whose output directory is
   * @p directory (its `checkpoint`, or `checkpoint.old` if a kill caught
   * the renaming of a new one); InputError if there is none, or if one of
   * its files is missing or differs from the checksums written with it
   * (named).
   */
  std::string
  checkpoint_of(const std::string &directory);
} // namespace xcrack

#endif

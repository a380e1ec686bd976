#ifndef xcrack_run_h
#define xcrack_run_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace xcrack
{
  /**
   * Run the scene of an already read parameter file: pick the dimension,
   * check every input, then solve and write results. Input errors are
   * thrown as InputError before anything is written. With a non-empty
   * @p resume_directory, continue the run checkpointed there.
   */
  void
  run(dealii::ParameterHandler &prm, const std::string &resume_directory = "");

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

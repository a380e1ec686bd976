#ifndef xcrack_run_h
#define xcrack_run_h

#include <deal.II/base/parameter_handler.h>

namespace xcrack
{
  /**
   * Run the scene of an already read parameter file: pick the dimension,
   * check every input, then solve and write results. Input errors are
   * thrown as InputError before anything is written.
   */
  void
  run(dealii::ParameterHandler &prm);
} // namespace xcrack

#endif

#include <xcrack/input_error.h>
#include <xcrack/run.h>
#include <xcrack/simulator.h>

#include <memory>

namespace xcrack
{
  namespace
  {
    template <int dim>
    void
    run_in(ParameterHandler &prm, const RunOptions &options)
    {
      // Construction reads and checks every input: whatever fails there
      // (a value ParameterHandler cannot convert, say 1e-400) is the
      // input's fault.
      std::unique_ptr<Simulator<dim>> simulator;
      try
        {
          simulator = std::make_unique<Simulator<dim>>(prm,
                                                       MPI_COMM_WORLD,
                                                       options.resume_directory,
                                                       options.check_only);
        }
      catch (const ExceptionBase &e)
        {
          throw InputError(message_of(e));
        }
      if (options.check_only)
        return;
      simulator->record_overrides(options.overrides);
      simulator->run();
    }
  } // namespace



  void
  run(ParameterHandler &prm, const RunOptions &options)
  {
    if (prm.get_integer("Dimension") == 2)
      run_in<2>(prm, options);
    else
      run_in<3>(prm, options);
  }
} // namespace xcrack

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
    run_in(ParameterHandler &prm, const std::string &resume_directory)
    {
      // Construction reads and checks every input: whatever fails there
      // (a value ParameterHandler cannot convert, say 1e-400) is the
      // input's fault.
      std::unique_ptr<Simulator<dim>> simulator;
      try
        {
          simulator = std::make_unique<Simulator<dim>>(prm,
                                                       MPI_COMM_WORLD,
                                                       resume_directory);
        }
      catch (const ExceptionBase &e)
        {
          throw InputError(message_of(e));
        }
      simulator->run();
    }
  } // namespace



  void
  run(ParameterHandler &prm, const std::string &resume_directory)
  {
    if (prm.get_integer("Dimension") == 2)
      run_in<2>(prm, resume_directory);
    else
      run_in<3>(prm, resume_directory);
  }
} // namespace xcrack

#include <xcrack/run.h>
#include <xcrack/simulator.h>

namespace xcrack
{
  void
  run(ParameterHandler &prm, const std::string &resume_directory)
  {
    if (prm.get_integer("Dimension") == 2)
      {
        Simulator<2> simulator(prm, MPI_COMM_WORLD, resume_directory);
        simulator.run();
      }
    else
      {
        Simulator<3> simulator(prm, MPI_COMM_WORLD, resume_directory);
        simulator.run();
      }
  }
} // namespace xcrack

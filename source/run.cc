#include <xcrack/simulator.h>
#include <xcrack/run.h>

namespace xcrack
{
  void
  run(ParameterHandler &prm)
  {
    if (prm.get_integer("Dimension") == 2)
      {
        Simulator<2> problem(prm);
        problem.run();
      }
    else
      {
        Simulator<3> problem(prm);
        problem.run();
      }
  }
} // namespace xcrack

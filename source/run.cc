#include <xcrack/elasticity.h>
#include <xcrack/run.h>

namespace xcrack
{
  void
  run(ParameterHandler &prm)
  {
    if (prm.get_integer("Dimension") == 2)
      {
        ElasticityProblem<2> problem(prm);
        problem.run();
      }
    else
      {
        ElasticityProblem<3> problem(prm);
        problem.run();
      }
  }
} // namespace xcrack

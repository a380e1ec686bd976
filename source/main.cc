/**
 * xcrack: fatigue crack propagation with the extended finite element method.
 *
 *   xcrack FILE.prm              run the scene of FILE.prm
 *   mpirun -np N xcrack FILE.prm the same on N ranks
 *   xcrack --resume DIR          continue the propagation run whose output
 *                                directory DIR holds a checkpoint
 *   xcrack --print-parameters    every parameter with default and documentation
 *
 * Exit codes: 0 success, 1 bad input (message names the culprit), 2 failure
 * during the computation (a file that cannot be written, the solver), 3 a
 * numerical failure (a value that is not finite, a singular system).
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <xcrack/input_error.h>
#include <xcrack/parameters.h>
#include <xcrack/run.h>

#include <iostream>
#include <string>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out << "Usage: xcrack FILE.prm\n"
        << "       mpirun -np N xcrack FILE.prm\n"
        << "       xcrack --resume OUTPUT_DIRECTORY\n"
        << "       xcrack --print-parameters\n";
  }
} // namespace

int
main(int argc, char *argv[])
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi_initialization(argc, argv, 1);
  const bool root = (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);

  const std::string argument = (argc > 1 ? argv[1] : "");
  if (argument == "--resume" && argc != 3)
    {
      if (root)
        {
          std::cerr << "xcrack: --resume takes one argument, the output "
                       "directory of the run to continue."
                    << std::endl;
          print_usage(std::cerr);
        }
      return 1;
    }
  if (argc != 2 && !(argc == 3 && argument == "--resume"))
    {
      if (root)
        print_usage(std::cerr);
      return 1;
    }

  try
    {
      ParameterHandler prm;
      xcrack::declare_all_parameters(prm);

      if (argument == "--print-parameters")
        {
          if (root)
            prm.print_parameters(std::cout, ParameterHandler::PRM);
          return 0;
        }
      if (argument == "--help" || argument == "-h")
        {
          if (root)
            print_usage(std::cout);
          return 0;
        }

      if (argument == "--resume")
        {
          // The run's own parameters, kept with the checkpoint; its results
          // stay where they are.
          const std::string directory = argv[2];
          xcrack::read_parameter_file(prm,
                                      xcrack::checkpoint_of(directory) +
                                        "/parameters.prm");
          prm.set("Output directory", directory);
          xcrack::run(prm, directory);
        }
      else
        {
          xcrack::read_parameter_file(prm, argument);
          xcrack::run(prm);
        }
    }
  catch (const xcrack::InputError &e)
    {
      if (root)
        std::cerr << "xcrack: input error: " << e.what() << std::endl;
      return 1;
    }
  catch (const xcrack::NumericalError &e)
    {
      if (root)
        std::cerr << "xcrack: numerical failure: " << e.what() << std::endl;
      return 3;
    }
  catch (const std::bad_alloc &)
    {
      // Out of memory before the first solve (the Simulator reports those
      // with their DoF count): the mesh or the input checks did not fit.
      std::cerr << "xcrack: error: out of memory while building the mesh "
                   "and checking the input: use a coarser mesh (Mesh/Initial "
                   "global refinement) or more ranks."
                << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "xcrack: error: " << e.what() << std::endl;
      return 2;
    }
  return 0;
}

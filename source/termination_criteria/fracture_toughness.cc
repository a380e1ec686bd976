#include <xcrack/front_move.h>
#include <xcrack/input_error.h>
#include <xcrack/material.h>
#include <xcrack/termination_criteria/fracture_toughness.h>

#include <sstream>

namespace xcrack
{
  namespace TerminationCriteria
  {
    template <int dim>
    void
    FractureToughness<dim>::parse_parameters(ParameterHandler &)
    {
      check_input(this->get_material().fracture_toughness > 0,
                  "Termination criteria: 'fracture toughness' needs "
                  "Material/Fracture toughness (K_Ic > 0).");
    }



    template <int dim>
    Verdict
    FractureToughness<dim>::check()
    {
      Verdict               verdict;
      const double          toughness = this->get_material().fracture_toughness;
      const FrontMove<dim> *worst     = nullptr;
      for (const FrontMove<dim> &m : this->get_front_moves())
        if (!worst || m.k_eq > worst->k_eq)
          worst = &m;
      if (worst && worst->k_eq >= toughness)
        {
          std::ostringstream reason;
          reason << "K_eq = " << worst->k_eq << " at (" << worst->point.position
                 << ") reached the fracture toughness K_Ic = " << toughness
                 << ": the part fails";
          verdict.stop    = true;
          verdict.failure = true;
          verdict.reason  = reason.str();
        }
      return verdict;
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           FractureToughness,
                           "fracture toughness",
                           "K_eq reaches Material/Fracture toughness somewhere "
                           "on a front: failure.")
  } // namespace TerminationCriteria
} // namespace xcrack

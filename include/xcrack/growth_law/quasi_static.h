#ifndef xcrack_growth_law_quasi_static_h
#define xcrack_growth_law_quasi_static_h

#include <xcrack/growth_law/interface.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace GrowthLaw
  {
    /**
     * `quasi-static`: no cycles; the load is the one that brings the most
     * loaded point to the fracture toughness K_Ic (Material/Fracture
     * toughness; Propagation reports this load factor K_Ic / max K_eq),
     * and the front advances `Maximum advance` there and in proportion to
     * (K_eq / K_Ic)^n elsewhere (`subsection Quasi-static`, `Exponent` n:
     * the larger, the more the advance concentrates where K_eq reaches
     * K_Ic).
     */
    template <int dim>
    class QuasiStatic : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      double
      rate(const double delta_k,
           const double k_max,
           const double load_ratio) const override;

      bool
      counts_cycles() const override;

    private:
      double exponent = 2;
    };
  } // namespace GrowthLaw
} // namespace xcrack

#endif

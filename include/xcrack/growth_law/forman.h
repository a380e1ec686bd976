#ifndef xcrack_growth_law_forman_h
#define xcrack_growth_law_forman_h

#include <xcrack/growth_law/interface.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace GrowthLaw
  {
    /**
     * `forman` (Forman, Kearney and Engle 1967): da/dN = C Delta K^m /
     * ((1 - R) K_Ic - Delta K) above the threshold (`subsection Forman`):
     * the rate runs away as K_max approaches the fracture toughness K_Ic
     * (Material/Fracture toughness), which Paris does not see.
     */
    template <int dim>
    class Forman : public Interface<dim>, public SimulatorAccess<dim>
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

      /// At Delta K >= (1 - R) K_Ic the part fails.
      std::string
      why_no_rate(const double delta_k,
                  const double k_max,
                  const double load_ratio) const override;

    private:
      PowerLawConstants constants;
      double            toughness = 0;
    };
  } // namespace GrowthLaw
} // namespace xcrack

#endif

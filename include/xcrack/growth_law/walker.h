#ifndef xcrack_growth_law_walker_h
#define xcrack_growth_law_walker_h

#include <xcrack/growth_law/interface.h>

namespace xcrack
{
  namespace GrowthLaw
  {
    /**
     * `walker` (Walker 1970): da/dN = C [Delta K / (1 - R)^(1 - gamma)]^m
     * above the threshold Delta K_th (`subsection Walker`): the mean stress
     * of the cycle matters, gamma = 1 is Paris, gamma < 1 makes a high R
     * grow faster at equal Delta K.
     */
    template <int dim>
    class Walker : public Interface<dim>
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

    private:
      PowerLawConstants constants;
      double            gamma = 0.5;
    };
  } // namespace GrowthLaw
} // namespace xcrack

#endif

#ifndef xcrack_growth_law_paris_h
#define xcrack_growth_law_paris_h

#include <xcrack/growth_law/interface.h>

namespace xcrack
{
  namespace GrowthLaw
  {
    /**
     * `paris` (Paris and Erdogan 1963): da/dN = C Delta K^m above the
     * threshold Delta K_th, 0 below (`subsection Paris`). The load ratio
     * enters only through Delta K.
     */
    template <int dim>
    class Paris : public Interface<dim>
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
    };
  } // namespace GrowthLaw
} // namespace xcrack

#endif

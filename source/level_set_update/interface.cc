#include <xcrack/level_set_update/interface.h>
#include <xcrack/simulator_access.h>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    void
    declare_parameters(ParameterHandler &prm)
    {
      using List = Plugins::PluginList<Interface<3>>;
      prm.declare_entry("Model name",
                        "geometric",
                        Patterns::Selection(List::pattern()),
                        "How the level sets follow the front:" +
                          List::documentation());
      List::declare_parameters(prm);
    }



    template <int dim>
    void
    Interface<dim>::check_advance(const double) const
    {}



    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator)
    {
      return create_plugin<dim, Interface<dim>>(
        prm.get("Model name"),
        "Propagation/Level set update/Model name",
        prm,
        simulator);
    }



    template class Interface<2>;
    template class Interface<3>;
    template std::unique_ptr<Interface<2>>
    create(ParameterHandler &, const Simulator<2> &);
    template std::unique_ptr<Interface<3>>
    create(ParameterHandler &, const Simulator<3> &);
  } // namespace LevelSetUpdate
} // namespace xcrack

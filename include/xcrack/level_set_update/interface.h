#ifndef xcrack_level_set_update_interface_h
#define xcrack_level_set_update_interface_h

#include <deal.II/base/parameter_handler.h>

#include <xcrack/crack/level_set_fields.h>
#include <xcrack/front_move.h>
#include <xcrack/plugins.h>

#include <memory>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  template <int dim>
  class Simulator;

  /**
   * How a crack's level sets follow its front (`subsection
   * Propagation/Level set update`, `Model name`): from the moves of the
   * points of its fronts (FrontMove: the old point with its frame, the kink
   * angle and the advance), the new lsn and lst on the current mesh. The
   * crack surface behind the old front must stay where it was.
   *
   * The seed's four methods fit here: `geometric` (the nodes near the
   * front projected on it), `crack mesh` (an explicit surface extended by
   * the advance), `upwind` (Hamilton-Jacobi on an auxiliary grid), and to
   * come `simplex` (the same on a simplicial split), each one more file
   * pair. What they share (the moves along a front by abscissa, the
   * projection on a front, the default band) is in front_track.h. A method that
   * keeps state across steps (a surface) saves and loads it with the
   * checkpoint.
   */
  namespace LevelSetUpdate
  {
    template <int dim>
    class Interface : public Plugins::InterfaceBase
    {
    public:
      /**
       * Move crack @p crack of @p fields by @p moves (the points of its
       * fronts where K was extracted, in the order of each front).
       * Collective: every rank passes the same moves.
       */
      virtual void
      update(const unsigned int                 crack,
             const std::vector<FrontMove<dim>> &moves,
             LevelSetFields<dim>               &fields) = 0;

      /**
       * Refuse settings that cannot work with steps of at most
       * @p maximum_advance (Propagation/Maximum advance), with an
       * InputError naming the entry: called once the parameters are read,
       * before any work.
       */
      virtual void
      check_advance(const double maximum_advance) const;
    };



    /// Declare `Model name` and every method's entries (in the current
    /// subsection).
    void
    declare_parameters(ParameterHandler &prm);

    /// The method `Model name` selects (in the current subsection).
    template <int dim>
    std::unique_ptr<Interface<dim>>
    create(ParameterHandler &prm, const Simulator<dim> &simulator);
  } // namespace LevelSetUpdate
} // namespace xcrack

#endif

#ifndef softgrasp_mechanics_dilatation_state_h
#define softgrasp_mechanics_dilatation_state_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <softgrasp/mechanics/element_dilatation.h>
#include <vector>

namespace softgrasp
{
  /// How one element's J~ and p~ follow the displacement increment du_e of
  /// its dofs: dJ~ = J_offset + J_rate du_e, dp~ = p_offset + p_rate du_e
  /// (coefficients; p in Pa, rates per m).
  struct DilatationLinearization
  {
    dealii::Vector<double>     J_offset, p_offset;
    dealii::FullMatrix<double> J_rate, p_rate;
  };

  /**
   * The element unknowns J~ and p~ of the mixed u-p-J formulation during
   * one Newton solve (ElementDilatation): recorded from the displacement
   * at the solve's first assembly (where they are its projections), then
   * updated with every Newton increment through the linearisation of the
   * last tangent, as the pressure and dilatation fields of deal.II
   * step-44. A large load increment then moves p~ by the linearised
   * response instead of by kappa times the second-order volume change of
   * the trial displacement, which keeps the tangent's pressure share, and
   * with it the displacement block, well-behaved. Inactive outside a
   * Newton solve: assemblies then project J~ and p~ from the displacement.
   * Indexed by the active cell index of the locally owned cells.
   */
  template <int dim> class DilatationState
  {
  public:
    /// Become active for @p n_active_cells cells; the next assembly records.
    void start(const unsigned int n_active_cells);
    /// Become inactive and free the memory.
    void clear();
    bool active() const;
    /// Whether the coefficients of every owned cell are recorded.
    bool recorded() const;
    /// Mark the recording assembly as complete (or not, if it failed).
    void set_recorded(const bool complete);

    /// The coefficients of cell @p index, or null before the recording.
    const DilatationCoefficients *coefficients(const unsigned int index) const;
    /// Keep the coefficients of cell @p index (recording assembly).
    void store(const unsigned int index, const DilatationCoefficients &c);
    /// Keep the linearisation of cell @p index (tangent assembly).
    void store(const unsigned int index, const DilatationLinearization &l);

    /// Remember the current coefficients as the start of an update.
    void begin_update();
    /// Coefficients = start + @p alpha times the increment that the
    /// displacement increment @p du (ghosted, m) implies.
    void apply_update(const dealii::DoFHandler<dim>               &dofs,
                      const dealii::TrilinosWrappers::MPI::Vector &du,
                      const double                                 alpha);

  private:
    /// One element's coefficients, start values and linearisation.
    struct Cell
    {
      DilatationCoefficients  current, start;
      DilatationLinearization linearization;
    };
    std::vector<Cell> cells;
    bool              is_active   = false;
    bool              is_recorded = false;
  };
} // namespace softgrasp

#endif

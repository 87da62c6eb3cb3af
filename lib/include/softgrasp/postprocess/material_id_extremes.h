#ifndef softgrasp_postprocess_material_id_extremes_h
#define softgrasp_postprocess_material_id_extremes_h

#include <deal.II/base/quadrature.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <map>
#include <ostream>
#include <softgrasp/materials/material_library.h>

namespace softgrasp
{
  /**
   * Extremes of the strain and stress measures over the quadrature points of
   * each material id, reduced over all MPI ranks: the table a study prints
   * to answer "how much did the skin / fat / muscle strain?". Measures:
   * largest e_max and smallest e_min (1; in the table also as Green-Lagrange
   * and logarithmic strains, which are monotone in e), smallest and largest J
   * (1), largest von Mises stress (Pa).
   */
  template <int dim> class MaterialIdExtremes
  {
  public:
    struct Extremes
    {
      double       e_max         = 0; ///< largest principal strain (1)
      double       e_min         = 0; ///< smallest principal strain (1)
      double       J_min         = 0; ///< smallest volume ratio (1)
      double       J_max         = 0; ///< largest volume ratio (1)
      double       von_mises_max = 0; ///< largest von Mises stress (Pa)
      unsigned int n_points      = 0; ///< quadrature points (all ranks)
    };

    /**
     * Evaluate over the locally owned cells; the displacement occupies
     * components [first_component, first_component + dim) of @p solution,
     * which must have ghost entries for the locally owned cells.
     */
    template <typename VectorType>
    void compute(const dealii::DoFHandler<dim> &dof_handler,
                 const VectorType              &solution,
                 const MaterialLibrary         &materials,
                 const dealii::Quadrature<dim> &quadrature,
                 const unsigned int             first_component = 0);

    const std::map<dealii::types::material_id, Extremes> &extremes() const;

    /// A table with one row per material id.
    dealii::TableHandler table(const MaterialLibrary &materials) const;

  private:
    std::map<dealii::types::material_id, Extremes> values;
  };
} // namespace softgrasp

#endif

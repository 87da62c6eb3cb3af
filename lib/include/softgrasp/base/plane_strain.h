#ifndef softgrasp_base_plane_strain_h
#define softgrasp_base_plane_strain_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace softgrasp
{
  /**
   * softgrasp evaluates constitutive laws in 3D. A 2D (dim = 2) model is a
   * plane-strain slice: F_33 = 1, F_i3 = F_3i = 0, and points sit at z = 0.
   */
  namespace PlaneStrain
  {
    template <int dim, typename Number>
    inline dealii::Tensor<2, 3, Number>
    to_3d(const dealii::Tensor<2, dim, Number> &F)
    {
      static_assert(dim == 2 || dim == 3, "dim must be 2 or 3");
      dealii::Tensor<2, 3, Number> F3;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          F3[i][j] = F[i][j];
      if (dim == 2)
        F3[2][2] = 1.0;
      return F3;
    }

    template <int dim>
    inline dealii::Point<3> to_3d(const dealii::Point<dim> &p)
    {
      dealii::Point<3> p3;
      for (unsigned int i = 0; i < dim; ++i)
        p3[i] = p[i];
      return p3;
    }
  } // namespace PlaneStrain
} // namespace softgrasp

#endif

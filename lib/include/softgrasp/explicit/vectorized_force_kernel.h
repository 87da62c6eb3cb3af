#ifndef softgrasp_explicit_vectorized_force_kernel_h
#define softgrasp_explicit_vectorized_force_kernel_h

#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <memory>
#include <softgrasp/materials/material_library.h>
#include <vector>

namespace softgrasp
{
  /**
   * The internal forces of InternalForceOperator with explicit SIMD over
   * cells (softgrasp/base/simd.h), independent of deal.II's vectorisation
   * width: each lane of a SIMD register holds one cell of a batch of cells
   * that share a material. Per batch: gather of the nodal displacements,
   * sum factorisation to the gradients at the Gauss points (Q1, Q2; 2D
   * plane strain and 3D), the stress from Material::first_piola_block()
   * (the material library's formulas, vectorised), and the transposed sum
   * factorisation and scatter of the forces. The inverse Jacobians and JxW
   * of every quadrature point are stored at set-up, so curved and distorted
   * cells cost the same as straight ones.
   *
   * Cells with constrained (hanging-node) DoFs are left to the caller's
   * reference path (other_cells()). The caller zeroes the destination,
   * updates the source's ghost values and compresses the destination.
   */
  template <int dim> class VectorizedForceKernel
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    /// Set up for the locally owned cells of @p data (its DoF handler
    /// and vector layout), on @p mapping with Gauss quadrature, p + 1 points
    /// per direction; @p mean_dilatation as in InternalForceOperator.
    VectorizedForceKernel(const dealii::MatrixFree<dim, double>   &data,
                          const dealii::Mapping<dim>              &mapping,
                          const dealii::AffineConstraints<double> &constraints,
                          const MaterialLibrary                   &materials,
                          const bool mean_dilatation);
    ~VectorizedForceKernel();

    /**
     * dst += f_int(src) over this kernel's cells, into owned and ghost
     * entries. @p energy accumulates int Psi dV (J) and @p min_J the
     * smallest det F of its points; inverted points (det F <= 0) get no
     * stress.
     */
    void apply(const VectorType &src,
               VectorType       &dst,
               double           &energy,
               double           &min_J) const;

    /// Cell batches of the MatrixFree object that this kernel leaves to
    /// the caller (cells with constrained DoFs).
    const std::vector<unsigned int> &other_cells() const;

    /// SIMD lanes (cells per batch) of this build.
    static unsigned int n_lanes();

  private:
    struct Data;
    std::unique_ptr<Data> d;
  };
} // namespace softgrasp

#endif

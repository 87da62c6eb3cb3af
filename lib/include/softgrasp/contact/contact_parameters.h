#ifndef softgrasp_contact_contact_parameters_h
#define softgrasp_contact_contact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <vector>

namespace softgrasp
{
  /// The subsection "Contact" of a .prm file.
  struct ContactParameters
  {
    /// Boundary ids of the deformable body's contact (slave) surface; empty
    /// means no contact.
    std::vector<dealii::types::boundary_id> slave_boundary_ids;
    double friction_coefficient = 0; ///< Coulomb mu (1), >= 0
    /// Complementarity parameter c as a multiple of 2 mu_0 h (N/m; mu_0
    /// the largest initial shear modulus, h the node's surface spacing).
    /// It steers only the active-set prediction, not the converged answer.
    double complementarity_factor = 0.1; ///< (1)

    static void declare_parameters(dealii::ParameterHandler &prm);
    void        parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace softgrasp

#endif

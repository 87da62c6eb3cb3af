#include <algorithm>
#include <cmath>
#include <limits>
#include <softgrasp/materials/material.h>
#include <softgrasp/mechanics/element_dilatation.h>

namespace softgrasp
{
  using namespace dealii;

  template <int dim>
  ElementDilatation<dim>::ElementDilatation(const unsigned int degree)
      : degree(degree)
      , n_functions(degree == 0 ? 1 : 1 + dim)
      , kernel(n_functions, n_functions)
  {
  }

  template <int dim>
  void
  ElementDilatation<dim>::set_up_basis(const std::vector<Point<dim>> &points,
                                       const std::vector<double>     &JxW,
                                       const std::vector<double>     &J)
  {
    n_points = points.size();
    values.assign(n_functions * n_points, 1.0);
    double volume = 0;
    for (const double w : JxW)
      volume += w;
    if (degree > 0)
    {
      Point<dim> center;
      for (unsigned int q = 0; q < n_points; ++q)
        center += JxW[q] / volume * points[q];
      const double h = std::pow(volume, 1.0 / dim);
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int q = 0; q < n_points; ++q)
          values[(1 + d) * n_points + q] = (points[q][d] - center[d]) / h;
    }

    // Mass matrix, its inverse and int N J dV (members: no allocation per
    // cell).
    mass.reinit(n_functions, n_functions);
    moments.reinit(n_functions);
    for (unsigned int q = 0; q < n_points; ++q)
      for (unsigned int a = 0; a < n_functions; ++a)
      {
        moments[a] += basis(a, q) * J[q] * JxW[q];
        for (unsigned int c = 0; c < n_functions; ++c)
          mass(a, c) += basis(a, q) * basis(c, q) * JxW[q];
      }
    M_inverse.reinit(n_functions, n_functions);
    M_inverse.invert(mass);
  }

  template <int dim> void ElementDilatation<dim>::evaluate_dilatation()
  {
    J_tilde.assign(n_points, 0.0);
    for (unsigned int q = 0; q < n_points; ++q)
    {
      for (unsigned int a = 0; a < n_functions; ++a)
        J_tilde[q] += J_coefficients[a] * basis(a, q);
      if (!(J_tilde[q] > 0) || !std::isfinite(J_tilde[q]))
        throw InvertedMaterialState(J_tilde[q]);
    }
  }

  template <int dim>
  void ElementDilatation<dim>::evaluate_pressure(const std::vector<double> &JxW)
  {
    double volume = 0;
    for (const double w : JxW)
      volume += w;
    p_tilde.assign(n_points, 0.0);
    p_mean = 0;
    for (unsigned int q = 0; q < n_points; ++q)
    {
      for (unsigned int a = 0; a < n_functions; ++a)
        p_tilde[q] += p_coefficients[a] * basis(a, q);
      p_mean += p_tilde[q] * JxW[q] / volume;
    }
  }

  template <int dim>
  void ElementDilatation<dim>::pressure_moments(const std::vector<double> &JxW,
                                                const VolumetricEnergy &energy,
                                                Vector<double> &result) const
  {
    result.reinit(n_functions);
    for (unsigned int q = 0; q < n_points; ++q)
    {
      const double dU = energy.first_derivative(J_tilde[q]);
      for (unsigned int a = 0; a < n_functions; ++a)
        result[a] += basis(a, q) * dU * JxW[q];
    }
  }

  template <int dim>
  void ElementDilatation<dim>::compute_kernel(const std::vector<double> &JxW,
                                              const VolumetricEnergy    &energy)
  {
    // A = M^-1 K_JJ M^-1, K_JJ = int N U''(J~) N^T dV
    FullMatrix<double> &K_JJ = scratch;
    K_JJ.reinit(n_functions, n_functions);
    curvature_min = std::numeric_limits<double>::max();
    for (unsigned int q = 0; q < n_points; ++q)
    {
      const double d2U = energy.second_derivative(J_tilde[q]);
      curvature_min    = std::min(curvature_min, d2U);
      for (unsigned int a = 0; a < n_functions; ++a)
        for (unsigned int e = 0; e < n_functions; ++e)
          K_JJ(a, e) += basis(a, q) * d2U * basis(e, q) * JxW[q];
    }
    FullMatrix<double> tmp(n_functions, n_functions);
    M_inverse.mmult(tmp, K_JJ);
    tmp.mmult(kernel, M_inverse);
  }

  template <int dim>
  void ElementDilatation<dim>::reinit(const std::vector<Point<dim>> &points,
                                      const std::vector<double>     &JxW,
                                      const std::vector<double>     &J,
                                      const VolumetricEnergy        &energy,
                                      const bool with_stiffness)
  {
    set_up_basis(points, JxW, J);
    // J~ = Pi_h J, then p~ = Pi_h U'(J~): both residuals vanish.
    J_coefficients.reinit(n_functions);
    M_inverse.vmult(J_coefficients, moments);
    evaluate_dilatation();
    Vector<double> &b = J_offset; // scratch here, zero on return
    pressure_moments(JxW, energy, b);
    p_coefficients.reinit(n_functions);
    M_inverse.vmult(p_coefficients, b);
    evaluate_pressure(JxW);
    J_offset.reinit(n_functions);
    p_offset.reinit(n_functions);
    if (with_stiffness)
      compute_kernel(JxW, energy);
  }

  template <int dim>
  void ElementDilatation<dim>::reinit(const std::vector<Point<dim>> &points,
                                      const std::vector<double>     &JxW,
                                      const std::vector<double>     &J,
                                      const VolumetricEnergy        &energy,
                                      const DilatationCoefficients  &given)
  {
    set_up_basis(points, JxW, J);
    J_coefficients = given.J;
    p_coefficients = given.p;
    evaluate_dilatation();
    evaluate_pressure(JxW);
    compute_kernel(JxW, energy);
    // R_p = int N J dV - M J~,  R_J = int N U'(J~) dV - M p~
    // (members as scratch: no allocation per cell)
    Vector<double> &R_p = residual_p, &R_J = residual_J, &Mc = mass_times;
    R_p = moments;
    Mc.reinit(n_functions);
    mass.vmult(Mc, J_coefficients);
    R_p -= Mc;
    pressure_moments(JxW, energy, R_J);
    mass.vmult(Mc, p_coefficients);
    R_J -= Mc;
    // dJ~ offset M^-1 R_p; dp~ offset s = M^-1 R_J + A R_p
    J_offset.reinit(n_functions);
    M_inverse.vmult(J_offset, R_p);
    p_offset.reinit(n_functions);
    M_inverse.vmult(p_offset, R_J);
    kernel.vmult_add(p_offset, R_p);
  }

  template <int dim>
  void
  ElementDilatation<dim>::get_coefficients(DilatationCoefficients &result) const
  {
    result.J = J_coefficients;
    result.p = p_coefficients;
  }

  template <int dim>
  const Vector<double> &ElementDilatation<dim>::pressure_offset() const
  {
    return p_offset;
  }

  template <int dim>
  const Vector<double> &ElementDilatation<dim>::dilatation_offset() const
  {
    return J_offset;
  }

  template <int dim>
  double ElementDilatation<dim>::augment(const double        gamma,
                                         const double        mu,
                                         FullMatrix<double> &shifted,
                                         FullMatrix<double> &result) const
  {
    // K_JJ >= U''_min M, hence A = M^-1 K_JJ M^-1 >= U''_min M^-1 and
    // A - w M^-1 >= A / 2 for w <= U''_min / 2.
    const double w = std::max(0.0, std::min(gamma, 0.5 * curvature_min));
    shifted        = kernel;
    shifted.add(-w, M_inverse);
    // (A'^-1 + c M)^-1 = A' (I + c M A')^-1, which needs no inverse of A'
    // (A' may be singular where U'' vanishes).
    FullMatrix<double> T(n_functions, n_functions), T_inverse(T);
    mass.mmult(T, shifted);
    T *= 1.0 / (mu + w);
    for (unsigned int a = 0; a < n_functions; ++a)
      T(a, a) += 1;
    T_inverse.invert(T);
    result.reinit(n_functions, n_functions);
    shifted.mmult(result, T_inverse);
    for (unsigned int a = 0; a < n_functions; ++a)
      for (unsigned int e = a + 1; e < n_functions; ++e)
        result(a, e) = result(e, a) = 0.5 * (result(a, e) + result(e, a));
    return w;
  }

  template <int dim>
  const FullMatrix<double> &ElementDilatation<dim>::mass_inverse() const
  {
    return M_inverse;
  }

  template <int dim> unsigned int ElementDilatation<dim>::n_basis() const
  {
    return n_functions;
  }

  template <int dim>
  double ElementDilatation<dim>::basis(const unsigned int a,
                                       const unsigned int q) const
  {
    return values[a * n_points + q];
  }

  template <int dim>
  double ElementDilatation<dim>::pressure(const unsigned int q) const
  {
    return p_tilde[q];
  }

  template <int dim>
  double ElementDilatation<dim>::dilatation(const unsigned int q) const
  {
    return J_tilde[q];
  }

  template <int dim> double ElementDilatation<dim>::mean_pressure() const
  {
    return p_mean;
  }

  template <int dim>
  const FullMatrix<double> &ElementDilatation<dim>::condensed_kernel() const
  {
    return kernel;
  }

  template class ElementDilatation<2>;
  template class ElementDilatation<3>;
} // namespace softgrasp

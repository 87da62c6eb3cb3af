#include <cmath>
#include <deal.II/physics/transformations.h>
#include <softgrasp/base/simd.h>
#include <softgrasp/materials/material.h>
#include <softgrasp/materials/tensor_algebra.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  InvertedMaterialState::InvertedMaterialState(const double J)
      : std::runtime_error("material evaluated at an inverted or non-finite "
                           "deformation, J = det F = " +
                           std::to_string(J))
      , J(J)
  {
  }

  Material::Material(std::string                     name,
                     std::unique_ptr<IsochoricModel> isochoric_model,
                     const VolumetricEnergy         &volumetric_energy,
                     const double                    density)
      : material_name(std::move(name))
      , model(std::move(isochoric_model))
      , volumetric(volumetric_energy)
      , rho0(density)
  {
  }

  void Material::evaluate_material(const Tensor<2, 3>         &F,
                                   const StructuralDirections &directions,
                                   const bool                  with_tangent,
                                   Response                   &response) const
  {
    evaluate_decoupled(F, directions, with_tangent, false, 0.0, response);
  }

  void Material::evaluate_material_with_pressure(
      const Tensor<2, 3>         &F,
      const StructuralDirections &directions,
      const double                pressure,
      const bool                  with_tangent,
      Response                   &response) const
  {
    evaluate_decoupled(F, directions, with_tangent, true, pressure, response);
  }

  void Material::evaluate_spatial_with_pressure(
      const Tensor<2, 3>         &F,
      const StructuralDirections &directions,
      const double                pressure,
      const bool                  with_tangent,
      Response                   &response) const
  {
    evaluate_decoupled(F, directions, with_tangent, true, pressure, response);
    push_forward(F, with_tangent, response);
  }

  void Material::push_forward(const Tensor<2, 3> &F,
                              const bool          with_tangent,
                              Response           &response)
  {
    response.stress = Physics::Transformations::Contravariant::push_forward(
        response.stress, F);
    if (with_tangent)
      response.tangent = Physics::Transformations::Contravariant::push_forward(
          response.tangent, F);
  }

  namespace
  {
    /// S = J U' C^{-1} + 2 f (X - (X:C)/3 C^{-1}), for double and batches.
    template <typename Number>
    SymmetricTensor<2, 3, Number>
    decoupled_stress(const Number                        &J,
                     const Number                        &dU,
                     const Number                        &f,
                     const SymmetricTensor<2, 3, Number> &Cinv,
                     const SymmetricTensor<2, 3, Number> &X,
                     const Number                        &XC)
    {
      return J * dU * Cinv + 2.0 * f * (X - (XC / 3.0) * Cinv);
    }
  } // namespace

  void Material::first_piola_batch(const Tensor<2, 3, VectorizedDouble> &F,
                                   const StructuralDirections     *directions,
                                   const unsigned int              n_lanes,
                                   Tensor<2, 3, VectorizedDouble> &P,
                                   VectorizedDouble               &energy,
                                   const VectorizedDouble *pressure) const
  {
    // P = F S with S from decoupled_stress(), written with
    // F C^{-1} = F^{-T} = cof(F) / J: no inverse of C, no product F S.
    const VectorizedDouble                        J = determinant(F);
    const SymmetricTensor<2, 3, VectorizedDouble> C =
        symmetrize(transpose(F) * F);
    VectorizedDouble f; // J^{-2/3}
    for (unsigned int lane = 0; lane < VectorizedDouble::size(); ++lane)
    {
      const double c = std::cbrt(J[lane]);
      f[lane]        = 1.0 / (c * c);
    }

    VectorizedDouble                        W_iso;
    SymmetricTensor<2, 3, VectorizedDouble> X;
    model->evaluate_batch(f * C, directions, n_lanes, W_iso, X);
    VectorizedDouble U = 0, dU = 0; // volumetric: scalar per lane
    if (pressure)
      dU = *pressure;
    else
      for (unsigned int lane = 0; lane < n_lanes; ++lane)
      {
        U[lane]  = volumetric.energy(J[lane]);
        dU[lane] = volumetric.first_derivative(J[lane]);
      }
    const VectorizedDouble XC = X * C;
    const VectorizedDouble a  = (J * dU - (2.0 / 3.0) * f * XC) / J;
    P = a * cofactor(F) + (2.0 * f) * (F * Tensor<2, 3, VectorizedDouble>(X));
    energy = U + W_iso;
    for (unsigned int lane = n_lanes; lane < VectorizedDouble::size(); ++lane)
    {
      energy[lane] = 0;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          P[i][j][lane] = 0;
    }
  }

  namespace
  {
    using V = simd::Double;

    /// det F of row-major F.
    V det3(const std::array<V, 9> &F)
    {
      return F[0] * (F[4] * F[8] - F[5] * F[7]) -
             F[1] * (F[3] * F[8] - F[5] * F[6]) +
             F[2] * (F[3] * F[7] - F[4] * F[6]);
    }

    /// C = F^T F in the symmetric order 00, 11, 22, 01, 02, 12.
    std::array<V, 6> right_cauchy_green(const std::array<V, 9> &F)
    {
      const auto column = [&](const unsigned int a, const unsigned int b)
      { return F[a] * F[b] + F[3 + a] * F[3 + b] + F[6 + a] * F[6 + b]; };
      return {{column(0, 0),
               column(1, 1),
               column(2, 2),
               column(0, 1),
               column(0, 2),
               column(1, 2)}};
    }

    /// J^{-1/3}: Newton's iteration y <- y (4 - J y^3)/3 from a quadratic
    /// start, at round-off after 5 steps for J in [0.3, 2] (all of tissue's
    /// range); chunks with a lane outside by cbrt lane by lane.
    V inverse_cube_root(const V &J)
    {
      if (!simd::stdx::all_of(J >= 0.3 && J <= 2.0))
        return 1.0 / simd::stdx::cbrt(J);
      const V x = J - 1.0;
      V       y = 1.0 - x * (1.0 / 3.0) + (2.0 / 9.0) * x * x;
      for (unsigned int i = 0; i < 5; ++i)
        y = y * (4.0 - J * y * y * y) * (1.0 / 3.0);
      return y;
    }

    std::array<V, 9> load_tensor(const std::array<PointValues, 9> &values,
                                 const unsigned int                k)
    {
      std::array<V, 9> F;
      for (unsigned int i = 0; i < 9; ++i)
        F[i] = simd::load(&values[i][k]);
      return F;
    }
  } // namespace

  void Material::first_piola_block(MaterialPointBlock &b) const
  {
    // Padding up to the widest SIMD width: F = I, p = 0.
    const unsigned int n = b.n_points;
    for (unsigned int k = n;
         k < (n + simd::max_width - 1) / simd::max_width * simd::max_width;
         ++k)
    {
      for (unsigned int i = 0; i < 9; ++i)
        b.F[i][k] = (i % 4 == 0) ? 1.0 : 0.0;
      b.pressure[k] = 0;
    }
    // Pass 1: J, f = J^{-2/3} and Cbar = f C for the isochoric model.
    IsochoricPointBlock &iso = b.isochoric;
    iso.n_points             = n;
    PointValues J, f;
    for (unsigned int k = 0; k < n; k += simd::width)
    {
      const auto F  = load_tensor(b.F, k);
      const V    j  = det3(F);
      const auto C  = right_cauchy_green(F);
      const V    y  = inverse_cube_root(j);
      const V    fk = y * y;
      simd::store(j, &J[k]);
      simd::store(fk, &f[k]);
      for (unsigned int i = 0; i < 6; ++i)
        simd::store(fk * C[i], &iso.Cbar[i][k]);
    }
    model->evaluate_block(iso);
    PointValues U, dU;
    if (!b.given_pressure)
      volumetric.evaluate_block(n, J, U, dU);
    // Pass 2: P = F S, written with F C^{-1} = cof(F) / J:
    //   P = (J U' - 2/3 f X:C) / J cof(F) + 2 f F X.
    const PointValues &pressure = b.given_pressure ? b.pressure : dU;
    for (unsigned int k = 0; k < n; k += simd::width)
    {
      const auto       F  = load_tensor(b.F, k);
      const auto       C  = right_cauchy_green(F);
      const V          j  = simd::load(&J[k]);
      const V          fk = simd::load(&f[k]);
      std::array<V, 6> X;
      for (unsigned int i = 0; i < 6; ++i)
        X[i] = simd::load(&iso.X[i][k]);
      const V XC = X[0] * C[0] + X[1] * C[1] + X[2] * C[2] +
                   2.0 * (X[3] * C[3] + X[4] * C[4] + X[5] * C[5]);
      const V a  = (j * simd::load(&pressure[k]) - (2.0 / 3.0) * fk * XC) / j;
      const V f2 = 2.0 * fk;
      // X as a full row-major matrix (symmetric)
      const std::array<V, 9> Xm = {
          {X[0], X[3], X[4], X[3], X[1], X[5], X[4], X[5], X[2]}};
      for (unsigned int r = 0; r < 3; ++r)
      {
        // rows of cof(F): cross products of the other two rows of F
        const unsigned int     r1 = (r + 1) % 3, r2 = (r + 2) % 3;
        const std::array<V, 3> cof = {
            {F[3 * r1 + 1] * F[3 * r2 + 2] - F[3 * r1 + 2] * F[3 * r2 + 1],
             F[3 * r1 + 2] * F[3 * r2 + 0] - F[3 * r1 + 0] * F[3 * r2 + 2],
             F[3 * r1 + 0] * F[3 * r2 + 1] - F[3 * r1 + 1] * F[3 * r2 + 0]}};
        for (unsigned int c = 0; c < 3; ++c)
        {
          const V FX = F[3 * r] * Xm[c] + F[3 * r + 1] * Xm[3 + c] +
                       F[3 * r + 2] * Xm[6 + c];
          simd::store(a * cof[c] + f2 * FX, &b.P[3 * r + c][k]);
        }
      }
      const V W = simd::load(&iso.energy[k]);
      simd::store(b.given_pressure ? W : W + simd::load(&U[k]), &b.energy[k]);
    }
  }

  void Material::evaluate_decoupled(const Tensor<2, 3>         &F,
                                    const StructuralDirections &directions,
                                    const bool                  with_tangent,
                                    const bool                  given_pressure,
                                    const double                pressure,
                                    Response                   &response) const
  {
    const double J = determinant(F);
    if (!(J > 0) || !std::isfinite(J))
      throw InvertedMaterialState(J);

    const SymmetricTensor<2, 3> C    = symmetrize(transpose(F) * F);
    const SymmetricTensor<2, 3> Cinv = invert(C);
    const double                f    = std::pow(J, -2.0 / 3.0);

    IsochoricModel::Response iso;
    model->evaluate(f * C, directions, with_tangent, iso);
    const SymmetricTensor<2, 3> &X  = iso.first_derivative;
    const double                 XC = X * C;

    // Volumetric part: S_vol = J U' C^{-1}.
    const double dU =
        given_pressure ? pressure : volumetric.first_derivative(J);
    response.energy =
        given_pressure ? iso.energy : volumetric.energy(J) + iso.energy;
    response.stress = decoupled_stress(J, dU, f, Cinv, X, XC);
    if (!with_tangent)
      return;

    const SymmetricTensor<4, 3> CinvCinv = outer_product(Cinv, Cinv);
    const SymmetricTensor<4, 3> CinvSym =
        TensorAlgebra::symmetric_product(Cinv, Cinv);
    const double d2U = given_pressure ? 0.0 : volumetric.second_derivative(J);

    // CC_vol = (J^2 U'' + J U') C^-1 (x) C^-1 - 2 J U' C^-1 (.) C^-1
    SymmetricTensor<4, 3> tangent =
        (J * J * d2U + J * dU) * CinvCinv - 2.0 * J * dU * CinvSym;

    // Isochoric: 4 [ P^T H P + X (x) df + df (x) X + (X:C) d2f ], with
    // P = f II + C (x) df, df = -f/3 C^-1, d2f = f/9 C^-1(x)C^-1 + f/3
    // C^-1(.)C^-1
    const SymmetricTensor<4, 3> &H   = iso.second_derivative;
    const SymmetricTensor<2, 3>  df  = (-f / 3.0) * Cinv;
    const SymmetricTensor<2, 3>  HC  = H * C;
    const SymmetricTensor<2, 3>  CH  = C * H;
    const double                 CHC = C * HC;
    const SymmetricTensor<4, 3>  d2f =
        (f / 9.0) * CinvCinv + (f / 3.0) * CinvSym;
    tangent += 4.0 * (f * f * H + f * outer_product(HC, df) +
                      f * outer_product(df, CH) + CHC * outer_product(df, df) +
                      outer_product(X, df) + outer_product(df, X) + XC * d2f);
    response.tangent = tangent;
  }

  void Material::evaluate_spatial(const Tensor<2, 3>         &F,
                                  const StructuralDirections &directions,
                                  const bool                  with_tangent,
                                  Response                   &response) const
  {
    evaluate_material(F, directions, with_tangent, response);
    push_forward(F, with_tangent, response);
  }

  double Material::strain_energy(const Tensor<2, 3>         &F,
                                 const StructuralDirections &directions) const
  {
    const double J = determinant(F);
    if (!(J > 0) || !std::isfinite(J))
      throw InvertedMaterialState(J);
    IsochoricModel::Response iso;
    model->evaluate(std::pow(J, -2.0 / 3.0) * symmetrize(transpose(F) * F),
                    directions,
                    false,
                    iso);
    return volumetric.energy(J) + iso.energy;
  }

  SymmetricTensor<2, 3>
  Material::cauchy_stress(const Tensor<2, 3>         &F,
                          const StructuralDirections &directions) const
  {
    Response response;
    evaluate_spatial(F, directions, false, response);
    return response.stress / determinant(F);
  }

  double Material::dilatational_wave_speed(
      const Tensor<2, 3> &F, const StructuralDirections &directions) const
  {
    Response response;
    evaluate_material(F, directions, true, response);
    const SymmetricTensor<2, 3> &S  = response.stress;
    const SymmetricTensor<4, 3> &CC = response.tangent;

    std::vector<Tensor<1, 3>> candidates;
    for (int a = -1; a <= 1; ++a)
      for (int b = -1; b <= 1; ++b)
        for (int c = 0; c <= 1; ++c)
        {
          // one representative of each +/- pair: 13 lattice directions
          const Tensor<1, 3> n({double(a), double(b), double(c)});
          if (n.norm() == 0 || (c == 0 && (b < 0 || (b == 0 && a < 0))))
            continue;
          candidates.push_back(n / n.norm());
        }
    const auto principal = eigenvectors(symmetrize(transpose(F) * F));
    for (const auto &p : principal)
      candidates.push_back(p.second);

    double max_eigenvalue = 0;
    for (const Tensor<1, 3> &N : candidates)
    {
      // Q_ik = (N.S.N) delta_ik + F_iM F_kP CC_MJPL N_J N_L
      Tensor<2, 3> B; // B_MP = CC_MJPL N_J N_L
      for (unsigned int M = 0; M < 3; ++M)
        for (unsigned int P = 0; P < 3; ++P)
          for (unsigned int Jx = 0; Jx < 3; ++Jx)
            for (unsigned int L = 0; L < 3; ++L)
              B[M][P] += CC[M][Jx][P][L] * N[Jx] * N[L];
      const Tensor<2, 3> Q =
          (N * (S * N)) * unit_symmetric_tensor<3>() + F * B * transpose(F);
      const auto eig = eigenvalues(symmetrize(Q));
      max_eigenvalue = std::max(max_eigenvalue, eig[0]);
    }
    return std::sqrt(max_eigenvalue / rho0);
  }

  double Material::reference_wave_speed() const
  {
    return std::sqrt((volumetric.bulk_modulus() +
                      4.0 / 3.0 * model->initial_shear_modulus()) /
                     rho0);
  }

  StructuralDirections Material::structural_directions(const Point<3> &X) const
  {
    const Point<3> own(transpose(frame_rotation) * (X - frame_translation));
    StructuralDirections d = model->structural_directions(own);
    for (unsigned int a = 0; a < d.n_directions; ++a)
      d.direction[a] = frame_rotation * d.direction[a];
    return d;
  }

  std::shared_ptr<const Material>
  Material::placed(const Tensor<2, 3> &rotation,
                   const Tensor<1, 3> &translation) const
  {
    auto copy = std::shared_ptr<Material>(new Material(*this));
    // Compose: first this material's own placement, then the new one.
    copy->frame_rotation    = rotation * frame_rotation;
    copy->frame_translation = rotation * frame_translation + translation;
    return copy;
  }

  double Material::density() const
  {
    return rho0;
  }

  double Material::initial_shear_modulus() const
  {
    return model->initial_shear_modulus();
  }

  double Material::bulk_modulus() const
  {
    return volumetric.bulk_modulus();
  }

  const std::string &Material::name() const
  {
    return material_name;
  }

  std::string Material::summary() const
  {
    std::ostringstream out;
    out << material_name << ": " << model->summary() << "; "
        << volumetric.name()
        << " volumetric energy, kappa = " << volumetric.bulk_modulus()
        << " Pa; rho_0 = " << rho0 << " kg/m^3";
    return out.str();
  }

  const IsochoricModel &Material::isochoric_model() const
  {
    return *model;
  }

  const VolumetricEnergy &Material::volumetric_energy() const
  {
    return volumetric;
  }
} // namespace softgrasp

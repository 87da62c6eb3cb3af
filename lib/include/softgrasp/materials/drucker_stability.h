#ifndef softgrasp_materials_drucker_stability_h
#define softgrasp_materials_drucker_stability_h

#include <softgrasp/materials/material.h>
#include <softgrasp/materials/material_fit.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * Drucker stability of a material along the homogeneous paths of
   * HomogeneousLoading (uniaxial and equibiaxial stress, in tension and
   * compression), as ABAQUS checks it: at each state the work of every
   * small increment, d tau : d(ln V), must be positive (tau the Kirchhoff
   * stress, ln V the logarithmic strain). For an isotropic material at
   * principal stretches l_i with Kirchhoff stresses tau_i this holds when
   *  - the matrix H_ij = d tau_i / d ln l_j is positive definite, and
   *  - each shear term (tau_i - tau_j) / (ln l_i - ln l_j) is positive
   *    (its limit H_ii - H_ij where l_i = l_j).
   * H comes from central differences of the material's own stress in
   * ln l_j. A material that is not stable in this sense has states where
   * a load can be held by more than one deformation (a stress-stretch
   * curve that turns back, or a shear that softens); a fitted model can be
   * unstable outside its data, so check it over the range the simulation
   * reaches. Fibre directions must lie along the coordinate axes.
   */
  struct DruckerStability
  {
    bool            stable  = true; ///< no state below failed
    HomogeneousTest test    = HomogeneousTest::uniaxial; ///< first failure
    double          stretch = 1; ///< its prescribed stretch (1)
    /// The smallest eigenvalue or shear term at that state over the
    /// initial shear modulus (1), negative where it failed; over all
    /// states if none did.
    double smallest = 0;

    /**
     * Check @p material at @p n stretches from @p min_stretch to
     * @p max_stretch (1; below 1 is compression) of each test, in the
     * order of increasing distance from l = 1, so that the first failure
     * is the one nearest to the reference state; @p tests: which paths.
     */
    static DruckerStability check(const Material    &material,
                                  const double       min_stretch,
                                  const double       max_stretch,
                                  const unsigned int n = 41,
                                  const std::vector<HomogeneousTest> &tests = {
                                      HomogeneousTest::uniaxial,
                                      HomogeneousTest::equibiaxial});

    /// One line for a log: "stable from l = a to b" or where it fails.
    std::string summary(const double min_stretch,
                        const double max_stretch) const;
  };
} // namespace softgrasp

#endif

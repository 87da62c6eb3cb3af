#ifndef softgrasp_postprocess_tissue_injury_h
#define softgrasp_postprocess_tissue_injury_h

#include <Eigen/Core>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <map>
#include <ostream>
#include <softgrasp/materials/material_library.h>
#include <string>
#include <vector>

namespace softgrasp
{
  template <int dim> class SolidSystem;
  template <int dim> class ContactSurface;
  template <int dim> class ContactOutput;
  class RigidBodySet;

  /**
   * The thresholds of an injury assessment ('Injury assessment'), parsed
   * once. The defaults and their sources are in doc/studies.md:
   * compressive engineering strains 1 - lambda_min of 0.40 and 0.65 (cell
   * death of skeletal muscle cells after hours and after about one hour of
   * sustained compression), the tensile strain 0.54 (mean failure strain of
   * excised human skin), and the contact pressures 4.3 kPa (capillary
   * closing pressure, 32 mmHg) and 1.9 MPa (pain onset on the deltoid
   * muscle of the upper arm, quasi-static contact).
   */
  struct InjuryThresholds
  {
    std::vector<double> compressive_strains = {0.40, 0.65};   ///< 1
    std::vector<double> tensile_strains     = {0.54};         ///< 1
    std::vector<double> pressures           = {4.3e3, 1.9e6}; ///< Pa

    /// Declare the subsection 'Injury assessment' in the current one.
    static void declare_parameters(dealii::ParameterHandler &prm);
    /// Parse it; @p parent is the current subsection's path, for messages.
    void parse_parameters(dealii::ParameterHandler &prm,
                          const std::string        &parent);
  };

  /**
   * Where an extreme value occurs: the material point (reference
   * position), where it is now, and the nearest rigid geom there.
   */
  struct InjuryLocation
  {
    double          value     = 0;
    Eigen::Vector3d reference = Eigen::Vector3d::Zero(); ///< X (m)
    Eigen::Vector3d current   = Eigen::Vector3d::Zero(); ///< x = X + u (m)
    std::string     nearest_geom;      ///< body/geom; empty: no rigid bodies
    double          geom_distance = 0; ///< signed, from x (m)
  };

  /**
   * A per-tissue injury assessment of a deformed solid (the source paper's
   * principal strains e_i = lambda_i - 1, Sec. II-C): per material id, the
   * largest e_max and the smallest e_min over the quadrature points and
   * where they occur, and the reference volume of the tissue strained
   * beyond each threshold (|e_min| = 1 - lambda_min for compression, e_max
   * for tension); on the contact surface (the skin), the largest contact
   * pressure and the deformed area of the nodes whose pressure exceeds
   * each threshold (nodal areas int N_j da, as the contact uses them).
   * Everything is reduced over all MPI ranks; SI units.
   */
  template <int dim> class TissueInjury
  {
  public:
    /// One row of the table: one tissue (material id).
    struct Tissue
    {
      dealii::types::material_id id = 0;
      std::string                name;
      double                     volume = 0;        ///< reference volume (m^3)
      InjuryLocation             e_max;             ///< largest e_max (1)
      InjuryLocation             e_min;             ///< smallest e_min (1)
      std::vector<double>        volume_compressed; ///< per threshold (m^3)
      std::vector<double>        volume_stretched;  ///< per threshold (m^3)
    };

    /// The contact surface's share of the assessment.
    struct SurfacePressure
    {
      InjuryLocation      maximum;          ///< largest contact pressure (Pa)
      double              contact_area = 0; ///< closed nodes' area (m^2)
      std::vector<double> area_above;       ///< per threshold (m^2)
    };

    /**
     * Assess @p system at its current displacement; @p contact and
     * @p output (both may be null) give the surface pressure, @p bodies at
     * @p time the nearest geom of every extreme. Collective.
     */
    void compute(const SolidSystem<dim>    &system,
                 const MaterialLibrary     &materials,
                 const ContactSurface<dim> *contact,
                 const ContactOutput<dim>  *output,
                 const RigidBodySet        &bodies,
                 const double               time,
                 const InjuryThresholds    &thresholds);

    /**
     * The strain part alone: the displacement occupies the first dim
     * components of @p solution (ghosted for the locally owned cells).
     * Collective. Clears the surface part and the nearest geoms.
     */
    template <typename VectorType>
    void compute_strains(const dealii::DoFHandler<dim> &dof_handler,
                         const dealii::Mapping<dim>    &mapping,
                         const VectorType              &solution,
                         const MaterialLibrary         &materials,
                         const InjuryThresholds        &thresholds);

    const std::vector<Tissue> &tissues() const
    {
      return rows;
    }
    const SurfacePressure &surface() const
    {
      return pressure;
    }

    /// Write the tissue rows to @p tissue_file and the surface pressure
    /// (one row per threshold) to @p surface_file, as CSV (SI units).
    void write_csv(const std::string &tissue_file,
                   const std::string &surface_file) const;

    /// A readable table (mm and percentages for the eye; the CSV is SI).
    void print(std::ostream &out) const;

  private:
    void compute_pressure(const SolidSystem<dim>    &system,
                          const ContactSurface<dim> &contact,
                          const ContactOutput<dim>  &output);
    /// One empty row per tissue of @p materials; returns the row of each
    /// material id.
    std::map<dealii::types::material_id, unsigned int>
    start_rows(const MaterialLibrary &materials);
    /// Sum the rows over the processes; drop tissues without cells (an id
    /// in the library but not in the mesh).
    void finish_rows(const MPI_Comm comm);

    InjuryThresholds    limits;
    std::vector<Tissue> rows;
    SurfacePressure     pressure;
    bool                has_contact = false;
  };
} // namespace softgrasp

#endif

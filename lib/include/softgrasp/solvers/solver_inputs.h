#ifndef softgrasp_solvers_solver_inputs_h
#define softgrasp_solvers_solver_inputs_h

#include <deal.II/base/parameter_handler.h>
#include <softgrasp/contact/contact_parameters.h>
#include <softgrasp/materials/material_library.h>
#include <softgrasp/mechanics/boundary_conditions.h>
#include <softgrasp/mechanics/solver_parameters.h>
#include <softgrasp/meshes/mesh_factory.h>
#include <softgrasp/rigid/rigid_body_set.h>
#include <string>
#include <utility>
#include <vector>

namespace softgrasp
{
  /**
   * Everything a Simulation is built from, as typed values: the
   * solver settings, the mesh (its generator and placement), the materials,
   * the boundary conditions, the contact settings and the rigid bodies.
   * parse() reads them from a .prm once; a study then changes the typed
   * values it owns (the end time of its recorded phases, the tissue's
   * placement, the rigid bodies of its kinematics file) before it builds
   * the solver, and never writes into the ParameterHandler.
   */
  template <int dim> struct SolverInputs
  {
    SolverParameters        solver;
    MeshFactory<dim>        mesh;
    MaterialLibrary         materials;
    BoundaryConditions<dim> boundary_conditions;
    ContactParameters       contact;
    RigidBodySet            bodies;
    /// The settings a resume must keep (name, value): the .prm's entries
    /// that decide the discretisation and the loads, and what a study adds
    /// (add_resume_setting()).
    std::vector<std::pair<std::string, std::string>> resume_settings;

    /// Parse all of them from @p prm (declared by
    /// Simulation::declare_parameters and read with its passes).
    static SolverInputs parse(dealii::ParameterHandler &prm);

    /// A setting that a study computed (e.g. the placement from its
    /// kinematics file), kept in checkpoints and checked on resume.
    void add_resume_setting(const std::string &name, const std::string &value);
  };
} // namespace softgrasp

#endif

# The labels 'quick' and 'long' (README, "Developing"). Names are CTest's
# without the build type ('contact/hertz' and 'contact/hertz.mpirun=2' for
# contact/hertz.release and contact/hertz.mpirun=2.release).
#
# quick: at least one test of every library module (base, materials,
# meshes, rigid, mechanics, contact, explicit, postprocess, io, solvers,
# grasp, mujoco), of the softgrasp program, of every example and of every
# study, chosen among the fast ones: `ctest -L quick` takes about 5 minutes
# on 2 cores after `--target all tests` (doc/benchmarks.md).
set(SOFTGRASP_QUICK_TESTS
  # library modules
  materials/tangent_consistency materials/presets materials/material_fit
  postprocess/principal_strains postprocess/tissue_injury.mpirun=2
  postprocess/corner_jacobian
  mechanics/bad_input mechanics/implicit_dynamics
  mechanics/cook_membrane_reference mechanics/potential_derivatives
  meshes/generated_shapes rigid/shapes io/kinematics_file
  contact/nodal_law explicit/internal_force solvers/custom_stepper
  mujoco/capsule_distance
  # base (parameters, output directory, restart) through the programs
  reliability/user_files reliability/initial_overlap restart/kill_and_resume
  style/floors package/find_package_consumer
  # the softgrasp program, every example, every study
  programs/softgrasp_no_file programs/softgrasp_hertz
  examples/tissue_curves examples/material_fit examples/cook_membrane
  examples/ironing
  examples/hertz_indentation examples/frictional_drag contact/drag_example_3d
  studies/sphere_squeeze studies/sphere_squeeze_missing_file
  studies/grasp_pull_sweep_bad_level)

# long: every test that took over 60 s on 2 cores under ctest -j2
# (doc/benchmarks.md, "Build and test times").
set(SOFTGRASP_LONG_TESTS
  mujoco/grasp_pull_fe mujoco/sweep_recovery
  contact/potential_agreement contact/potential_agreement.mpirun=2
  contact/drag_potential contact/drag_calculix contact/drag_integrators
  contact/hertz_faces contact/drag_faces contact/drag_faces_2d
  contact/drag_increments_3d mujoco/arm_grasp_quasi_static)

# Label the tests of the current directory: the category (the name up to
# its '/'), and 'quick' and 'long' from the lists above.
function(softgrasp_label_tests)
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach(test ${tests})
    string(REGEX REPLACE "\\.(release|debug)$" "" name "${test}")
    string(REGEX REPLACE "/.*$" "" category "${name}")
    set_property(TEST ${test} APPEND PROPERTY LABELS ${category})
    if(name IN_LIST SOFTGRASP_QUICK_TESTS OR name IN_LIST SOFTGRASP_LONG_TESTS)
      set_property(GLOBAL APPEND PROPERTY SOFTGRASP_LABELLED_TESTS ${name})
    endif()
    if(name IN_LIST SOFTGRASP_QUICK_TESTS)
      set_property(TEST ${test} APPEND PROPERTY LABELS quick)
    endif()
    if(name IN_LIST SOFTGRASP_LONG_TESTS)
      set_property(TEST ${test} APPEND PROPERTY LABELS long)
    endif()
  endforeach()
endfunction()

# In a configuration with every test (MuJoCo and the examples found), each
# name of the lists must be a test: a renamed test would otherwise leave
# the quick check without it, silently.
function(softgrasp_check_labelled_tests)
  if(NOT SOFTGRASP_HAVE_MUJOCO OR NOT SOFTGRASP_BUILD_EXAMPLES)
    return()
  endif()
  get_property(labelled GLOBAL PROPERTY SOFTGRASP_LABELLED_TESTS)
  foreach(name ${SOFTGRASP_QUICK_TESTS} ${SOFTGRASP_LONG_TESTS})
    if(NOT name IN_LIST labelled)
      message(FATAL_ERROR "tests/labels.cmake names '${name}', which is no "
        "test. Fix: use the test's name as 'ctest -N' shows it, without "
        "'.release'.")
    endif()
  endforeach()
endfunction()

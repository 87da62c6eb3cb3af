#ifndef softgrasp_materials_material_library_h
#define softgrasp_materials_material_library_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <map>
#include <memory>
#include <ostream>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/materials/material.h>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The materials of a simulation, one per material id, configured in a
   * parameter file:
   * @code
   * subsection Materials
   *   set Material ids = 0, 1
   *   subsection Material 0
   *     set Preset = skin                 # or none
   *   end
   *   subsection Material 1
   *     set Model   = Mooney-Rivlin       # any registered model
   *     set Density = 1000                # kg/m^3
   *     subsection Volumetric
   *       set Energy          = Simo-Taylor
   *       set Poisson's ratio = 0.45      # or: set Bulk modulus = ... (Pa)
   *     end
   *     subsection Mooney-Rivlin
   *       set C10 = 2e3                   # Pa
   *       set C01 = 5e2                   # Pa
   *     end
   *   end
   * end
   * @endcode
   * The per-id subsections depend on "Material ids", so a parameter file
   * with materials is read with MaterialLibrary::parse_input() (several
   * passes over the same text), not with ParameterHandler::parse_input()
   * alone. Entries the user sets override those of a selected preset.
   */
  class MaterialLibrary
  {
  public:
    /// Declare "Materials/Material ids" (the per-id subsections come later).
    static void declare_parameters(dealii::ParameterHandler &prm);

    /// Declare one material's entries in the current subsection of @p prm.
    static void declare_material_parameters(dealii::ParameterHandler &prm);

    /**
     * For --print-parameters of a program whose entries are declared in
     * @p prm (with declare_parameters()): add the 'Program' entry and one
     * material subsection ('Materials/Material 0', standing for every id)
     * and print every parameter with its documentation to @p out.
     */
    static void print_parameters(dealii::ParameterHandler &prm,
                                 std::ostream             &out);

    /**
     * Read @p filename into @p prm (which holds the caller's declarations
     * plus declare_parameters()): declare the per-id subsections, apply the
     * selected presets, then parse the file strictly, so that a misspelled
     * entry is an error naming its line.
     */
    static void parse_input(dealii::ParameterHandler &prm,
                            const std::string        &filename);

    /**
     * As parse_input(), from the text of a parameter file; @p source names
     * it in error messages. Parse errors become an InputError.
     */
    static void
    parse_input_from_string(dealii::ParameterHandler &prm,
                            const std::string        &text,
                            const std::string        &source = "input string");

    /// Build the material of the current subsection of @p prm.
    static std::shared_ptr<const Material>
    create_material(dealii::ParameterHandler &prm,
                    const std::string        &path,
                    const std::string        &name);

    /**
     * Build a material from @p fragment, the entries of one material
     * subsection in .prm syntax (e.g. "set Model = neo-Hookean ..."); for
     * programs and benchmarks that configure a material in code.
     */
    static std::shared_ptr<const Material>
    create_from_fragment(const std::string &fragment, const std::string &name);

    /// Build a material from a preset alone (with its default parameters).
    static std::shared_ptr<const Material>
    create_preset(const std::string &preset_name);

    /// Build all materials from a parsed @p prm.
    void parse_parameters(dealii::ParameterHandler &prm);

    /// The material of @p id; throws an InputError listing configured ids.
    const Material &get(const dealii::types::material_id id) const;

    /// Shared ownership of the material of @p id.
    std::shared_ptr<const Material>
    get_shared(const dealii::types::material_id id) const;

    std::vector<dealii::types::material_id> material_ids() const;

    /**
     * One line per material whose constants lie far outside any tissue's
     * (initial shear modulus outside 1 Pa to 10 GPa: soft tissues have
     * about 100 Pa to 10 MPa, cortical bone about 5 GPa; density outside
     * 100 to 10000 kg/m^3), naming the material, the value and the likely
     * cause (a unit); empty if none. Such a run is not refused: a user may
     * mean it, but its results rarely are what was meant.
     */
    std::vector<std::string> implausible_constants() const;

    /// Add or replace the material of @p id (for programs that build in code).
    void set(const dealii::types::material_id id,
             std::shared_ptr<const Material>  material);

    /**
     * Add this library's declaration passes to @p reader: declare the
     * per-id subsections, then apply each id's preset. Programs that read
     * further dynamic sections add their own passes to the same reader.
     */
    static void add_passes(ParameterReader &reader);

  private:
    std::map<dealii::types::material_id, std::shared_ptr<const Material>>
        materials;
  };
} // namespace softgrasp

#endif

#ifndef softgrasp_materials_tissue_presets_h
#define softgrasp_materials_tissue_presets_h

#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * Named tissue presets: a material model, its parameters and a density
   * from the literature, written as a fragment of a material subsection of a
   * parameter file. A user selects one with "set Preset = <name>" in a
   * "Materials/Material <id>" subsection; any entry the user also sets in
   * that subsection overrides the preset's. Every value is cited in
   * doc/materials.md.
   */
  class TissuePresets
  {
  public:
    struct Preset
    {
      std::string name;        ///< e.g. "skin"
      std::string description; ///< one line, with the source
      std::string parameters;  ///< .prm fragment for a material subsection
    };

    /// All presets, in a fixed order.
    static const std::vector<Preset> &all();

    /// The preset named @p name; throws an InputError listing valid names.
    static const Preset &get(const std::string &name);

    /// "none|skin|...", for a Patterns::Selection.
    static std::string selection();
  };
} // namespace softgrasp

#endif

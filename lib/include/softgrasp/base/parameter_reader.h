#ifndef softgrasp_base_parameter_reader_h
#define softgrasp_base_parameter_reader_h

#include <deal.II/base/parameter_handler.h>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace softgrasp
{
  /**
   * Reads a .prm file whose set of subsections depends on its own content
   * (a subsection per material id, per boundary id, ...). The text is parsed
   * leniently once per declaration pass; each pass reads what is known so
   * far and declares further entries (or applies presets). A final strict
   * parse then reports any misspelled or undeclared entry.
   *
   * deal.II's parse errors become InputErrors naming the file, the line and
   * the fix.
   */
  class ParameterReader
  {
  public:
    using Pass = std::function<void(dealii::ParameterHandler &)>;

    /// Register a pass; passes run in the order they were added.
    void add_pass(Pass pass);

    /// The text of @p filename; an InputError if it cannot be opened.
    static std::string file_text(const std::string &filename);

    /// Parse the file @p filename into @p prm.
    void read_file(dealii::ParameterHandler &prm,
                   const std::string        &filename) const;

    /**
     * Every entry of @p prm as "Section/Subsection/Name" and its value, in
     * the order deal.II prints them (for records such as the settings a
     * checkpoint must be resumed with).
     */
    static std::vector<std::pair<std::string, std::string>>
    flatten(const dealii::ParameterHandler &prm);

    /**
     * Record that the top-level subsection @p section is read by @p programs
     * only (e.g. "arm_grasp or grasp_pull_sweep"), so that a file given to
     * another program is said to belong to them. Called from a static
     * initializer next to the declaration of that subsection; returns true.
     */
    static bool register_program_section(const std::string &section,
                                         const std::string &programs);

    /**
     * The program this process runs (@p name, e.g. "arm_grasp") and the
     * other programs whose files it reads as well (the softgrasp program
     * runs every solver example's file; mujoco_grasp sphere_squeeze's).
     * A file whose top-level entry 'Program' names a program outside these
     * is refused before anything else is read, with an InputError that
     * names the program the file is written for. Files without the entry
     * are read as before. Called once by each program's main().
     */
    static void set_program(const std::string              &name,
                            const std::vector<std::string> &reads_files_of);

    /**
     * Declare the top-level entry 'Program' in @p prm (its default: the
     * name given to set_program()); declaring it again resets it to that
     * default. Every file read by read_string() may carry it, and
     * --print-parameters shows it.
     */
    static void declare_program_entry(dealii::ParameterHandler &prm);

    /// Parse @p text (from @p source, used in messages) into @p prm.
    void read_string(dealii::ParameterHandler &prm,
                     const std::string        &text,
                     const std::string        &source) const;

  private:
    std::vector<Pass> passes;
  };
} // namespace softgrasp

#endif

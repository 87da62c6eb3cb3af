#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_reader.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  void ParameterReader::add_pass(Pass pass)
  {
    passes.push_back(std::move(pass));
  }

  std::string ParameterReader::file_text(const std::string &filename)
  {
    std::ifstream file(filename);
    if (!file)
      throw InputError("Cannot open the parameter file '" + filename +
                       "'. Fix: check the path; it is read relative to the "
                       "working directory.");
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
  }

  void ParameterReader::read_file(ParameterHandler  &prm,
                                  const std::string &filename) const
  {
    read_string(prm, file_text(filename), filename);
  }

  void ParameterReader::read_string(ParameterHandler  &prm,
                                    const std::string &text,
                                    const std::string &source) const
  {
    try
    {
      for (const Pass &pass : passes)
      {
        prm.parse_input_from_string(text, "", /*skip_undefined=*/true);
        pass(prm);
      }
      prm.parse_input_from_string(text, "", /*skip_undefined=*/false);
    }
    catch (const ExceptionBase &e)
    {
      // deal.II names the source "<input string>"; name the file instead.
      std::ostringstream info;
      e.print_info(info);
      std::string       message     = info.str();
      const std::string placeholder = "<input string>";
      for (auto pos = message.find(placeholder); pos != std::string::npos;
           pos      = message.find(placeholder, pos + source.size() + 2))
        message.replace(pos, placeholder.size(), "<" + source + ">");
      throw InputError("The parameter file '" + source +
                       "' cannot be read: " + Utilities::trim(message) +
                       " Fix: check the spelling and the allowed values; "
                       "the programs list every parameter with its "
                       "documentation (see doc/parameters/).");
    }
  }
} // namespace softgrasp

#include <algorithm>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <softgrasp/base/fatal_error.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/parameter_reader.h>
#include <softgrasp/base/run_manifest.h>
#include <sstream>

namespace softgrasp
{
  using namespace dealii;

  namespace
  {
    /// Top-level subsections that only some programs read, and which.
    std::map<std::string, std::string> &program_sections()
    {
      static std::map<std::string, std::string> sections;
      return sections;
    }

    /// The program this process runs, and the programs whose files it reads.
    struct ProgramIdentity
    {
      std::string              name;
      std::vector<std::string> reads;
    };

    ProgramIdentity &identity()
    {
      static ProgramIdentity program;
      return program;
    }

    /// The value of the top-level entry 'Program' of @p text, or "".
    std::string program_entry(const std::string &text)
    {
      std::istringstream in(text);
      std::string        line;
      int                depth = 0;
      while (std::getline(in, line))
      {
        std::istringstream words(line);
        std::string        keyword;
        words >> keyword;
        if (keyword == "subsection")
          ++depth;
        else if (keyword == "end")
          --depth;
        else if (keyword == "set" && depth == 0)
        {
          const auto equals = line.find('=');
          const auto name   = line.substr(0, equals);
          if (equals != std::string::npos &&
              Utilities::trim(name.substr(name.find("set") + 3)) == "Program")
            return Utilities::trim(line.substr(equals + 1));
        }
      }
      return "";
    }

    /// Refuse @p text (from @p source) if its 'Program' is not one this
    /// program reads.
    void check_program(const std::string &text, const std::string &source)
    {
      const ProgramIdentity &self    = identity();
      const std::string      written = program_entry(text);
      if (self.name.empty() || written.empty() || written == self.name ||
          std::find(self.reads.begin(), self.reads.end(), written) !=
              self.reads.end())
        return;
      std::string reads = self.reads.empty()
                              ? " (it reads its own files only)"
                              : ", which reads its own files and those of ";
      for (std::size_t i = 0; i < self.reads.size(); ++i)
        reads += (i == 0 ? "" : ", ") + self.reads[i];
      throw InputError("The parameter file '" + source + "' is written for " +
                       written + " (its entry 'Program = " + written +
                       "'), and this program is " + self.name + reads +
                       ". Fix: run " + written + " " + source + ", or give " +
                       self.name + " one of its own files (" + self.name +
                       " --print-parameters lists its entries).");
    }

    /// The end of the message for a file deal.II cannot read: the fix, and
    /// for "There is no such subsection to be entered: <name>" the program
    /// the file belongs to.
    std::string unreadable_file_advice(const std::string &message)
    {
      const std::string marker = "There is no such subsection to be entered";
      const auto        at     = message.find(marker);
      auto              colon  = message.find(':', at);
      std::string       section =
          at == std::string::npos || colon == std::string::npos
                    ? ""
                    : Utilities::trim(message.substr(colon + 1));
      section          = section.substr(0, section.find('\n'));
      const auto known = program_sections().find(Utilities::trim(section));
      if (known != program_sections().end())
        return " This program has no subsection '" + known->first +
               "': the file is written for " + known->second +
               ". Fix: run it with that program, or give this program "
               "one of its own files (--print-parameters lists its "
               "entries).";
      const std::string fix =
          " Fix: check the spelling and the allowed values; the programs "
          "list every parameter with its documentation (see "
          "doc/parameters/).";
      if (at == std::string::npos)
        return fix;
      return " This program has no such subsection: the file may be "
             "written for another softgrasp program (each program's "
             "subsections are listed in doc/parameters/ and by "
             "--print-parameters)." +
             fix;
    }

    struct Line
    {
      unsigned int number;
      std::size_t  indent;
      std::string  text; ///< trimmed, without comment
    };

    /// The logical lines of a .prm text (comments removed, continuation
    /// lines joined); an InputError at the first line with binary data.
    std::vector<Line> logical_lines(const std::string &text,
                                    const std::string &source)
    {
      std::vector<Line>  lines;
      std::istringstream in(text);
      std::string        raw, pending;
      unsigned int       number = 0, first = 0;
      while (std::getline(in, raw))
      {
        ++number;
        for (std::size_t c = 0; c < raw.size(); ++c)
        {
          const auto byte = static_cast<unsigned char>(raw[c]);
          if (byte < 32 && raw[c] != '\t' && raw[c] != '\r')
            throw InputError(
                "The parameter file '" + source + "' has binary data on " +
                "line " + std::to_string(number) + " (byte " +
                std::to_string(byte) + " at column " + std::to_string(c + 1) +
                "). Fix: a .prm file is plain text; check that the right "
                "file is given and that it is not damaged.");
        }
        const auto hash = raw.find('#');
        if (hash != std::string::npos)
          raw.erase(hash);
        if (pending.empty())
          first = number;
        std::string trimmed = Utilities::trim(raw);
        if (!trimmed.empty() && trimmed.back() == '\\')
        {
          trimmed.pop_back();
          pending += trimmed + " ";
          continue;
        }
        const std::size_t indent =
            pending.empty() ? raw.find_first_not_of(" \t") : 0;
        const std::string joined = Utilities::trim(pending + trimmed);
        pending.clear();
        if (!joined.empty())
          lines.push_back({first, indent, joined});
      }
      return lines;
    }

    /// Check the nesting of subsection/end and the form of set lines, so
    /// that a structural error names its own line.
    void check_structure(const std::string &text, const std::string &source)
    {
      const auto lines = logical_lines(text, source);
      const auto fail  = [&](const unsigned int line, const std::string &what)
      {
        throw InputError("The parameter file '" + source + "' cannot be " +
                         "read: line " + std::to_string(line) + ": " + what);
      };
      std::vector<std::size_t> open; // indices into lines
      for (std::size_t i = 0; i < lines.size(); ++i)
      {
        const std::string &t       = lines[i].text;
        const std::string  keyword = t.substr(0, t.find_first_of(" \t"));
        if (keyword == "subsection")
          open.push_back(i);
        else if (keyword == "end")
        {
          if (t != "end")
            fail(lines[i].number,
                 "'" + t + "': 'end' stands alone on its line.");
          if (open.empty())
            fail(lines[i].number,
                 "'end' without a matching 'subsection'. Fix: remove it, or "
                 "add the 'subsection' it closes.");
          open.pop_back();
        }
        else if (keyword == "set")
        {
          if (t.find('=') == std::string::npos)
            fail(lines[i].number,
                 "'" + t + "' has no '='. Fix: write 'set <name> = <value>'.");
        }
        else if (keyword != "include")
          fail(lines[i].number,
               "'" + t +
                   "' is not a 'set', 'subsection' or 'end' line. Fix: "
                   "write 'set <name> = <value>', or comment it out with '#'.");
      }
      if (open.empty())
        return;
      // The first unclosed subsection; where its 'end' was probably meant
      // to be: before the next line indented no deeper than it.
      const Line &unclosed = lines[open.front()];
      std::string hint;
      for (std::size_t i = open.front() + 1; i < lines.size(); ++i)
        if (lines[i].indent <= unclosed.indent)
        {
          hint =
              " (probably before line " + std::to_string(lines[i].number) + ")";
          break;
        }
      fail(unclosed.number,
           "'" + unclosed.text + "' is never closed. Fix: add its 'end'" +
               hint + ".");
    }
  } // namespace

  void ParameterReader::add_pass(Pass pass)
  {
    passes.push_back(std::move(pass));
  }

  std::string ParameterReader::file_text(const std::string &filename)
  {
    std::ifstream file(filename);
    if (std::filesystem::is_directory(filename))
      throw InputError("The parameter file '" + filename +
                       "' is a directory. Fix: give the path of a .prm "
                       "file.");
    if (!file)
      throw InputError("Cannot open the parameter file '" + filename +
                       "'. Fix: check the path; it is read relative to the "
                       "working directory.");
    RunManifest::protect_input(filename);
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
    check_structure(text, source);
    check_program(text, source);
    declare_program_entry(prm);
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
      // some of deal.II's messages leave the name's bracket open
      const std::string open = "<input string:";
      for (auto pos = message.find(open); pos != std::string::npos;
           pos      = message.find(open, pos + source.size() + 3))
        message.replace(pos, open.size(), "<" + source + ">:");
      throw InputError("The parameter file '" + source + "' cannot be read: " +
                       printable(Utilities::trim(message)) +
                       unreadable_file_advice(message));
    }
  }

  void ParameterReader::set_program(const std::string              &name,
                                    const std::vector<std::string> &reads)
  {
    identity() = {name, reads};
  }

  void ParameterReader::declare_program_entry(ParameterHandler &prm)
  {
    // declared anew if declared already (deal.II replaces the entry; its
    // value is set by the parse that follows)
    const std::string name = identity().name;
    prm.declare_entry(
        "Program",
        name,
        Patterns::Anything(),
        "The softgrasp program this file is written for" +
            (name.empty() ? std::string() : " (here: " + name + ")") +
            ". A program refuses a file written for another program and "
            "names that program; a file without this entry is read by any "
            "program that knows its entries. Unit: none.");
  }

  bool ParameterReader::register_program_section(const std::string &section,
                                                 const std::string &programs)
  {
    program_sections()[section] = programs;
    return true;
  }

  std::vector<std::pair<std::string, std::string>>
  ParameterReader::flatten(const ParameterHandler &prm)
  {
    std::ostringstream printed;
    prm.print_parameters(printed, ParameterHandler::ShortPRM);
    std::vector<std::pair<std::string, std::string>> entries;
    std::vector<std::string>                         path;
    std::istringstream                               lines(printed.str());
    for (std::string line; std::getline(lines, line);)
    {
      line = Utilities::trim(line);
      if (line.rfind("subsection ", 0) == 0)
        path.push_back(Utilities::trim(line.substr(11)));
      else if (line == "end" && !path.empty())
        path.pop_back();
      else if (line.rfind("set ", 0) == 0)
      {
        const auto  equal = line.find('=');
        std::string name  = Utilities::trim(line.substr(4, equal - 4));
        for (auto it = path.rbegin(); it != path.rend(); ++it)
          name = *it + "/" + name;
        entries.emplace_back(name,
                             equal == std::string::npos
                                 ? ""
                                 : Utilities::trim(line.substr(equal + 1)));
      }
    }
    return entries;
  }
} // namespace softgrasp

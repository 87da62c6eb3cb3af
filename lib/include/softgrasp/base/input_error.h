#ifndef softgrasp_base_input_error_h
#define softgrasp_base_input_error_h

#include <stdexcept>
#include <string>

namespace softgrasp
{
  /**
   * The exception softgrasp throws for bad user input: a parameter out of
   * range, an unknown name, a missing file. Its message names the cause and
   * the fix, and carries no C++ file/line noise, so a program can print it
   * to a user as it is.
   */
  class InputError : public std::runtime_error
  {
  public:
    explicit InputError(const std::string &message);
  };
} // namespace softgrasp

#endif

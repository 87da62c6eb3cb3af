#ifndef softgrasp_base_scoped_subsection_h
#define softgrasp_base_scoped_subsection_h

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace softgrasp
{
  /**
   * Enters a subsection of a ParameterHandler for the lifetime of this
   * object and leaves it in the destructor, also when an exception passes
   * (an InputError of an entry read inside): the handler stays at the
   * level where it was, usable by a caller that catches the error and goes
   * on (a fit that tries parameters the model refuses).
   */
  class ScopedSubsection
  {
  public:
    ScopedSubsection(dealii::ParameterHandler &prm, const std::string &name)
        : prm(prm)
    {
      prm.enter_subsection(name);
    }
    ~ScopedSubsection()
    {
      prm.leave_subsection();
    }
    ScopedSubsection(const ScopedSubsection &)            = delete;
    ScopedSubsection &operator=(const ScopedSubsection &) = delete;

  private:
    dealii::ParameterHandler &prm;
  };
} // namespace softgrasp

#endif

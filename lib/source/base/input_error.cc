#include <softgrasp/base/input_error.h>

namespace softgrasp
{
  InputError::InputError(const std::string &message)
      : std::runtime_error(message)
  {
  }
} // namespace softgrasp

#include <chrono>
#include <cstdio>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <iostream>
#include <softgrasp/base/fatal_error.h>
#include <sstream>
#include <thread>

namespace softgrasp
{
  std::string printable(const std::string &text)
  {
    std::string out;
    for (const char c : text)
    {
      const auto byte = static_cast<unsigned char>(c);
      if ((byte >= 32 && byte < 127) || c == '\n' || c == '\t')
        out += c;
      else
      {
        char escaped[8];
        std::snprintf(escaped, sizeof(escaped), "\\x%02X", byte);
        out += escaped;
      }
    }
    return out;
  }

  std::string error_message(const std::exception &e)
  {
    if (const auto *deal = dynamic_cast<const dealii::ExceptionBase *>(&e))
    {
      std::ostringstream info;
      deal->print_info(info);
      const std::string text = dealii::Utilities::trim(info.str());
      return printable(text.empty() ? deal->get_exc_name() : text);
    }
    return printable(e.what());
  }

  ErrorCommunicator::ErrorCommunicator(MPI_Comm parent)
  {
    MPI_Comm_dup(parent, &comm);
  }

  ErrorCommunicator::~ErrorCommunicator()
  {
    MPI_Comm_free(&comm);
  }

  ErrorCommunicator::operator MPI_Comm() const
  {
    return comm;
  }

  int fatal_error(const std::exception &e, MPI_Comm error_comm)
  {
    const std::string message = error_message(e);
    int               rank = 0, size = 1;
    MPI_Comm_rank(error_comm, &rank);
    MPI_Comm_size(error_comm, &size);
    if (size > 1)
    {
      MPI_Request request;
      MPI_Ibarrier(error_comm, &request);
      int        all_failed = 0;
      const auto start      = std::chrono::steady_clock::now();
      while (!all_failed &&
             std::chrono::steady_clock::now() - start < std::chrono::seconds(5))
      {
        MPI_Test(&request, &all_failed, MPI_STATUS_IGNORE);
        if (!all_failed)
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      if (!all_failed)
      {
        std::cerr << "\nError (on MPI rank " << rank << " of " << size
                  << "; ending the whole job): " << message << std::endl;
        MPI_Abort(error_comm, 1);
      }
    }
    if (rank == 0)
      std::cerr << "\nError: " << message << std::endl;
    return 1;
  }
} // namespace softgrasp

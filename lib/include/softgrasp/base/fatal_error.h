#ifndef softgrasp_base_fatal_error_h
#define softgrasp_base_fatal_error_h

#include <exception>
#include <mpi.h>
#include <string>

namespace softgrasp
{
  /**
   * The text of an exception as a user should read it: deal.II's
   * exceptions without their "An error occurred in line ..." banner, and
   * bytes that are not printable (NUL, binary data from a damaged file)
   * shown as \xNN, so that nothing cuts the message short.
   */
  std::string error_message(const std::exception &e);

  /// @p text with every byte that is not printable ASCII (except
  /// newlines and tabs) shown as \xNN.
  std::string printable(const std::string &text);

  /**
   * A duplicate of a program's communicator, made before any work, on
   * which the ranks that caught an error meet (apart from the work's own
   * collective operations, in which the other ranks may be waiting).
   */
  class ErrorCommunicator
  {
  public:
    explicit ErrorCommunicator(MPI_Comm comm);
    ~ErrorCommunicator();
    ErrorCommunicator(const ErrorCommunicator &)            = delete;
    ErrorCommunicator &operator=(const ErrorCommunicator &) = delete;
                       operator MPI_Comm() const;

  private:
    MPI_Comm comm;
  };

  /**
   * End a program after @p e was caught on this rank, with exit code 1 and
   * the message on stderr, and never a hang: the ranks that caught an error
   * meet on @p error_comm (a duplicate of the program's communicator made
   * before any work). If all ranks arrive within a few seconds (an input
   * error that every rank sees), rank 0 prints the message and 1 is
   * returned. Otherwise the other ranks are waiting in a collective
   * operation; this rank prints the message (with its rank) and aborts the
   * whole job (MPI_Abort with code 1).
   */
  int fatal_error(const std::exception &e, MPI_Comm error_comm);
} // namespace softgrasp

#endif

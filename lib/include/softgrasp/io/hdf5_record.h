#ifndef softgrasp_io_hdf5_record_h
#define softgrasp_io_hdf5_record_h

#include <deal.II/base/hdf5.h>
#include <functional>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * Small HDF5 files that a program writes and a later run reads back (a
   * study's per-stage results): written whole or not at all, read with
   * errors that name the file and the fix. On one rank only.
   */
  namespace Hdf5Record
  {
    /// Create @p filename under a temporary name, let @p fill write into
    /// it, check it and rename it; throws std::runtime_error naming the
    /// file and the cause.
    void write(const std::string                               &filename,
               const std::function<void(dealii::HDF5::File &)> &fill);

    /**
     * Read access to a record, opened read-only (several processes may
     * read one file at once). Objects are named by their path in the file
     * ("" or "/" the root, "link_0"); every failure throws
     * std::runtime_error naming the object.
     */
    class Reader
    {
    public:
      explicit Reader(const std::string &filename);
      ~Reader();
      Reader(const Reader &)            = delete;
      Reader &operator=(const Reader &) = delete;

      /// The string attribute @p name of @p object.
      std::string string_attribute(const std::string &object,
                                   const std::string &name) const;
      /// The numeric attribute @p name of @p object (as a double).
      double number_attribute(const std::string &object,
                              const std::string &name) const;
      /// The one-dimensional dataset at @p path (empty if it has no
      /// values).
      std::vector<double> vector(const std::string &path) const;

    private:
      hid_t file;
    };

    /// Open @p filename and let @p read read it. A missing, damaged or
    /// unexpected file (any exception of the HDF5 library or of @p read)
    /// becomes an InputError naming the file, the cause and @p fix.
    void read(const std::string                         &filename,
              const std::string                         &fix,
              const std::function<void(const Reader &)> &read);

    /// A one-dimensional dataset @p name of @p values (may be empty).
    void write_vector(dealii::HDF5::Group       &group,
                      const std::string         &name,
                      const std::vector<double> &values);
  } // namespace Hdf5Record
} // namespace softgrasp

#endif

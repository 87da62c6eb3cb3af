#ifndef softgrasp_io_hdf5_record_h
#define softgrasp_io_hdf5_record_h

#include <functional>
#include <hdf5.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace softgrasp
{
  /**
   * The project's one layer over the HDF5 library for the files it writes
   * and reads back (histories, study records, the kinematics file): written
   * whole or not at all, in the HDF5 1.10 format (metadata with checksums)
   * with Fletcher-32 checksummed datasets, so damage is refused on reading;
   * read with errors that name the object and the cause. On one rank only.
   * See doc/reliability.md ("HDF5 files").
   */
  namespace Hdf5Record
  {
    /// An HDF5 identifier, closed when it goes out of scope.
    class Handle
    {
    public:
      Handle(const hid_t id, herr_t (*close)(hid_t));
      Handle(Handle &&other) noexcept;
      Handle(const Handle &)            = delete;
      Handle &operator=(const Handle &) = delete;
      Handle &operator=(Handle &&other) noexcept;
      ~Handle();
      operator hid_t() const
      {
        return id;
      }

    private:
      hid_t id;
      herr_t (*close)(hid_t);
    };

    /// How string attributes are stored: variable-length (as deal.II and
    /// h5py write them) or fixed-length (the kinematics file, schema 2).
    enum class Strings
    {
      variable_length,
      fixed_length
    };

    /// An object being written (group or dataset) that takes attributes.
    class Object
    {
    public:
      Object(Handle &&handle, const Strings strings);
      void attribute(const std::string &name, const std::string &value);
      void attribute(const std::string &name, const double value);
      void attribute(const std::string &name, const int value);

    protected:
      Handle  handle;
      Strings strings;
    };

    /// A group being written; the file itself is the root group.
    class Group : public Object
    {
    public:
      using Object::Object;
      /// The subgroup @p path ("a" or "a/b"), created level by level if it
      /// does not exist yet.
      Group group(const std::string &path);
      /// A dataset @p name of @p rows x @p columns values (row by row;
      /// one-dimensional if @p columns is 1), checksummed.
      Object dataset(const std::string         &name,
                     const std::vector<double> &values,
                     const hsize_t              rows,
                     const hsize_t              columns = 1);
      /// A one-dimensional dataset of all @p values (may be empty).
      Object vector(const std::string &name, const std::vector<double> &values)
      {
        return dataset(name, values, values.size());
      }
    };

    /// Create @p filename under a temporary name, let @p fill write into
    /// its root group, check it and rename it; throws std::runtime_error
    /// naming the file and the cause.
    void write(const std::string                  &filename,
               const std::function<void(Group &)> &fill,
               const Strings strings = Strings::variable_length);

    /**
     * What is wrong with a file being read, in words that follow the file's
     * name ("has no dataset '/time'"), and its kind, for the caller's fix.
     */
    class ReadError : public std::runtime_error
    {
    public:
      enum class Kind
      {
        missing,     ///< no such object
        wrong_type,  ///< an attribute of another type
        wrong_shape, ///< a dataset of another shape
        damaged,     ///< HDF5 cannot read it (checksum, truncation)
        not_finite,  ///< NaN or inf where a number is needed
        invalid      ///< readable, but the values make no sense
      };
      ReadError(const Kind kind, const std::string &what);
      Kind kind;
    };

    /**
     * Read access to a file, opened read-only (several processes may read
     * one file at once). Objects are named by their path in the file ("/"
     * the root, "/link_0"; a leading '/' may be left out); every failure
     * throws a ReadError.
     */
    class Reader
    {
    public:
      explicit Reader(const std::string &filename);

      /// Whether the group or dataset @p path exists.
      bool has(const std::string &path) const;
      /// Throws ReadError::missing unless the group @p path exists.
      void require_group(const std::string &path) const;
      /// Whether @p object has the attribute @p name.
      bool has_attribute(const std::string &object,
                         const std::string &name) const;
      /// The string attribute @p name of @p object.
      std::string string_attribute(const std::string &object,
                                   const std::string &name) const;
      /// The numeric attribute @p name of @p object (as a double).
      double number_attribute(const std::string &object,
                              const std::string &name) const;
      /// The one-dimensional dataset at @p path (empty if it has no
      /// values).
      std::vector<double> vector(const std::string &path) const;
      /// The dataset at @p path of @p rows (0: any number) x @p columns
      /// finite values, row by row.
      std::vector<double> table(const std::string &path,
                                const hsize_t      rows,
                                const hsize_t      columns) const;
      /// The file's end of data in bytes (more than its size: truncated).
      haddr_t end_of_data() const;

    private:
      Handle file;
    };

    /// Open @p filename and let @p read read it. A missing, damaged or
    /// unexpected file (any exception of the HDF5 library or of @p read)
    /// becomes an InputError naming the file, the cause and @p fix.
    void read(const std::string                         &filename,
              const std::string                         &fix,
              const std::function<void(const Reader &)> &read);

    /// Switches HDF5's own printing of its error stack off while it lives
    /// (the errors thrown say more).
    class QuietErrors
    {
    public:
      QuietErrors();
      ~QuietErrors();
      QuietErrors(const QuietErrors &)            = delete;
      QuietErrors &operator=(const QuietErrors &) = delete;

    private:
      H5E_auto2_t function;
      void       *data;
    };
  } // namespace Hdf5Record
} // namespace softgrasp

#endif

#include <cmath>
#include <cstdio>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/fatal_error.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/run_manifest.h>
#include <softgrasp/io/hdf5_record.h>

namespace softgrasp
{
  namespace Hdf5Record
  {
    Handle::Handle(const hid_t id, herr_t (*close)(hid_t))
        : id(id)
        , close(close)
    {
    }

    Handle::Handle(Handle &&other) noexcept
        : id(other.id)
        , close(other.close)
    {
      other.id = -1;
    }

    Handle &Handle::operator=(Handle &&other) noexcept
    {
      if (this != &other)
      {
        if (id >= 0)
          close(id);
        id       = other.id;
        close    = other.close;
        other.id = -1;
      }
      return *this;
    }

    Handle::~Handle()
    {
      if (id >= 0)
        close(id);
    }

    namespace
    {
      /// Throws std::runtime_error if an HDF5 call failed.
      hid_t checked(const hid_t result, const std::string &what)
      {
        if (result < 0)
          throw std::runtime_error("HDF5 could not " + what);
        return result;
      }

      /// A scalar attribute @p name of @p type on @p object, written.
      void write_attribute(const hid_t        object,
                           const std::string &name,
                           const hid_t        type,
                           const void        *value)
      {
        const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
        const Handle attribute(checked(H5Acreate2(object,
                                                  name.c_str(),
                                                  type,
                                                  space,
                                                  H5P_DEFAULT,
                                                  H5P_DEFAULT),
                                       "create the attribute '" + name + "'"),
                               H5Aclose);
        checked(H5Awrite(attribute, type, value),
                "write the attribute '" + name + "'");
      }
    } // namespace

    Object::Object(Handle &&handle, const Strings strings)
        : handle(std::move(handle))
        , strings(strings)
    {
    }

    void Object::attribute(const std::string &name, const std::string &value)
    {
      const Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
      if (strings == Strings::fixed_length)
      {
        H5Tset_size(type, value.size() + 1);
        write_attribute(handle, name, type, value.c_str());
      }
      else
      {
        // UTF-8, as deal.II and h5py read and write them
        H5Tset_cset(type, H5T_CSET_UTF8);
        H5Tset_size(type, H5T_VARIABLE);
        const char *pointer = value.c_str();
        write_attribute(handle, name, type, &pointer);
      }
    }

    void Object::attribute(const std::string &name, const double value)
    {
      write_attribute(handle, name, H5T_NATIVE_DOUBLE, &value);
    }

    void Object::attribute(const std::string &name, const int value)
    {
      write_attribute(handle, name, H5T_NATIVE_INT, &value);
    }

    Group Group::group(const std::string &path)
    {
      Handle level(-1, H5Gclose);
      for (const auto &name : dealii::Utilities::split_string_list(path, '/'))
      {
        const hid_t parent = level < 0 ? hid_t(handle) : hid_t(level);
        const hid_t id     = H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0
                                 ? H5Gopen2(parent, name.c_str(), H5P_DEFAULT)
                                 : H5Gcreate2(parent,
                                          name.c_str(),
                                          H5P_DEFAULT,
                                          H5P_DEFAULT,
                                          H5P_DEFAULT);
        level =
            Handle(checked(id, "create the group '" + path + "'"), H5Gclose);
      }
      if (level < 0)
        throw std::logic_error("a group without a name");
      return Group(std::move(level), strings);
    }

    Object Group::dataset(const std::string         &name,
                          const std::vector<double> &values,
                          const hsize_t              rows,
                          const hsize_t              columns)
    {
      if (values.size() != rows * columns)
        throw std::logic_error("the dataset '" + name + "' has " +
                               std::to_string(values.size()) +
                               " values for its shape");
      const int     rank    = columns == 1 ? 1 : 2;
      const hsize_t dims[2] = {rows, columns};
      const Handle  space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
      // One chunk with a Fletcher-32 checksum: a damaged value is refused
      // on reading instead of being used.
      const Handle properties(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
      if (!values.empty())
      {
        H5Pset_chunk(properties, rank, dims);
        H5Pset_fletcher32(properties);
      }
      Handle set(checked(H5Dcreate2(handle,
                                    name.c_str(),
                                    H5T_NATIVE_DOUBLE,
                                    space,
                                    H5P_DEFAULT,
                                    properties,
                                    H5P_DEFAULT),
                         "create the dataset '" + name + "'"),
                 H5Dclose);
      if (!values.empty())
        checked(H5Dwrite(set,
                         H5T_NATIVE_DOUBLE,
                         H5S_ALL,
                         H5S_ALL,
                         H5P_DEFAULT,
                         values.data()),
                "write the dataset '" + name + "'");
      return Object(std::move(set), strings);
    }

    void write(const std::string                  &filename,
               const std::function<void(Group &)> &fill,
               const Strings                       strings)
    {
      RunManifest::note(filename);
      const std::string temporary = AtomicFile::temporary_name(filename);
      try
      {
        const QuietErrors quiet;
        // The HDF5 1.10 file format: its metadata (object headers with the
        // attributes) carries checksums, so damage is detected on reading.
        const Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
        H5Pset_libver_bounds(access, H5F_LIBVER_V110, H5F_LIBVER_V110);
        Group root(Handle(checked(H5Fcreate(temporary.c_str(),
                                            H5F_ACC_TRUNC,
                                            H5P_DEFAULT,
                                            access),
                                  "create the file"),
                          H5Fclose),
                   strings);
        fill(root);
      }
      catch (const std::exception &e)
      {
        std::remove(temporary.c_str());
        throw std::runtime_error(AtomicFile::write_error(
            filename, "the HDF5 library failed: " + error_message(e)));
      }
      // Errors at closing are only printed by HDF5: check the file.
      if (H5Fis_hdf5(temporary.c_str()) <= 0)
      {
        std::remove(temporary.c_str());
        throw std::runtime_error(
            AtomicFile::write_error(filename, "the HDF5 file is incomplete"));
      }
      AtomicFile::commit(temporary, filename);
    }

    ReadError::ReadError(const Kind kind, const std::string &what)
        : std::runtime_error(what)
        , kind(kind)
    {
    }

    namespace
    {
      using Kind = ReadError::Kind;

      /// "/a/b" of "a/b", "/a/b" or "" (the root).
      std::string absolute(const std::string &path)
      {
        return path.empty() || path[0] != '/' ? "/" + path : path;
      }

      /// @p object's attribute @p name, opened.
      Handle open_attribute(const hid_t        file,
                            const std::string &object,
                            const std::string &name)
      {
        const std::string path = absolute(object);
        if (H5Aexists_by_name(file, path.c_str(), name.c_str(), H5P_DEFAULT) <=
            0)
          throw ReadError(Kind::missing,
                          "has no attribute '" + name + "' on '" + path + "'");
        const hid_t attribute = H5Aopen_by_name(
            file, path.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
        if (attribute < 0)
          throw ReadError(Kind::damaged,
                          "has an unreadable attribute '" + name + "' on '" +
                              path + "' (the file is damaged)");
        return Handle(attribute, H5Aclose);
      }

      /// The @p n values of the dataset @p set (named @p where in errors).
      std::vector<double>
      read_values(const hid_t set, const hsize_t n, const std::string &where)
      {
        std::vector<double> values(n);
        if (n > 0 && H5Dread(set,
                             H5T_NATIVE_DOUBLE,
                             H5S_ALL,
                             H5S_ALL,
                             H5P_DEFAULT,
                             values.data()) < 0)
          throw ReadError(Kind::damaged,
                          "has an unreadable dataset " + where +
                              " (the file is damaged or truncated)");
        return values;
      }

      /// The string value of @p attribute (fixed or variable length).
      std::string read_string(const hid_t attribute, const hid_t type)
      {
        if (H5Tis_variable_str(type) > 0)
        {
          char *value = nullptr;
          if (H5Aread(attribute, type, &value) < 0 || value == nullptr)
            throw std::runtime_error("unreadable");
          const std::string result(value);
          H5free_memory(value);
          return result;
        }
        std::string value(H5Tget_size(type), '\0');
        if (H5Aread(attribute, type, value.data()) < 0)
          throw std::runtime_error("unreadable");
        return value.substr(0, value.find('\0'));
      }
    } // namespace

    Reader::Reader(const std::string &filename)
        : file(H5Fopen(filename.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose)
    {
      if (file < 0)
        throw ReadError(Kind::damaged, "is damaged: HDF5 cannot open it");
    }

    bool Reader::has(const std::string &path) const
    {
      // Every link on the way must exist before H5Lexists may ask for it.
      std::string so_far;
      for (std::size_t next = 1; next <= path.size(); ++next)
        if (next == path.size() || path[next] == '/')
        {
          so_far = absolute(path.substr(0, next));
          if (so_far != "/" &&
              H5Lexists(file, so_far.c_str(), H5P_DEFAULT) <= 0)
            return false;
        }
      return true;
    }

    void Reader::require_group(const std::string &path) const
    {
      const Handle group(
          has(path) ? H5Gopen2(file, absolute(path).c_str(), H5P_DEFAULT) : -1,
          H5Gclose);
      if (group < 0)
        throw ReadError(Kind::missing, "has no group '" + absolute(path) + "'");
    }

    bool Reader::has_attribute(const std::string &object,
                               const std::string &name) const
    {
      return has(object) &&
             H5Aexists_by_name(
                 file, absolute(object).c_str(), name.c_str(), H5P_DEFAULT) > 0;
    }

    std::string Reader::string_attribute(const std::string &object,
                                         const std::string &name) const
    {
      const Handle      attribute = open_attribute(file, object, name);
      const Handle      type(H5Aget_type(attribute), H5Tclose);
      const std::string where = "'" + name + "' on '" + absolute(object) + "'";
      if (H5Tget_class(type) != H5T_STRING)
        throw ReadError(Kind::wrong_type,
                        "has a non-string attribute " + where);
      try
      {
        return read_string(attribute, type);
      }
      catch (const std::runtime_error &)
      {
        throw ReadError(Kind::damaged,
                        "has an unreadable attribute " + where +
                            " (the file is damaged)");
      }
    }

    double Reader::number_attribute(const std::string &object,
                                    const std::string &name) const
    {
      const Handle attribute = open_attribute(file, object, name);
      double       value     = 0;
      if (H5Aread(attribute, H5T_NATIVE_DOUBLE, &value) < 0)
        throw ReadError(Kind::wrong_type,
                        "has an attribute '" + name + "' on '" +
                            absolute(object) + "' that is not a number");
      return value;
    }

    std::vector<double> Reader::vector(const std::string &path) const
    {
      if (!has(path))
        throw ReadError(Kind::missing,
                        "has no dataset '" + absolute(path) + "'");
      const Handle set(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose);
      const Handle space(H5Dget_space(set), H5Sclose);
      if (set < 0 || H5Sget_simple_extent_ndims(space) != 1)
        throw ReadError(Kind::wrong_shape,
                        "has the dataset '" + absolute(path) +
                            "' that is not one-dimensional");
      return read_values(
          set, H5Sget_simple_extent_npoints(space), "'" + absolute(path) + "'");
    }

    std::vector<double> Reader::table(const std::string &path,
                                      const hsize_t      rows,
                                      const hsize_t      columns) const
    {
      const std::string where = "'" + absolute(path) + "'";
      if (!has(path))
        throw ReadError(Kind::missing, "has no dataset " + where);
      const Handle set(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose);
      const Handle space(H5Dget_space(set), H5Sclose);
      hsize_t      dims[2] = {0, 1};
      const int    rank    = H5Sget_simple_extent_ndims(space);
      if (rank >= 1 && rank <= 2)
        H5Sget_simple_extent_dims(space, dims, nullptr);
      if (rank < 1 || rank > 2 || (rank == 1 && columns != 1) ||
          (rank == 2 && dims[1] != columns) || (rows > 0 && dims[0] != rows))
        throw ReadError(
            Kind::wrong_shape,
            "has the dataset " + where + " with shape " +
                std::to_string(dims[0]) +
                (rank == 2 ? " x " + std::to_string(dims[1]) : "") +
                ", expected " + (rows > 0 ? std::to_string(rows) : "n") +
                (columns > 1 ? " x " + std::to_string(columns) : ""));
      const std::vector<double> values =
          read_values(set, dims[0] * columns, where);
      for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
          throw ReadError(Kind::not_finite,
                          "has a non-finite value (NaN or inf) in " + where +
                              " at row " + std::to_string(i / columns));
      return values;
    }

    haddr_t Reader::end_of_data() const
    {
      haddr_t end = 0;
      if (H5Fget_eoa(file, &end) < 0)
        throw ReadError(Kind::damaged, "is damaged: HDF5 cannot open it");
      return end;
    }

    void read(const std::string                         &filename,
              const std::string                         &fix,
              const std::function<void(const Reader &)> &read)
    {
      const QuietErrors quiet;
      std::string       cause;
      if (!std::filesystem::exists(filename))
        cause = "does not exist";
      else if (H5Fis_hdf5(filename.c_str()) <= 0)
        cause = "is not an HDF5 file (damaged or truncated)";
      else
        try
        {
          const Reader reader(filename);
          read(reader);
          return;
        }
        catch (const ReadError &e)
        {
          cause = e.what();
        }
        catch (const std::exception &e)
        {
          cause = "cannot be read: " + error_message(e);
        }
      throw InputError("The file '" + filename + "' " + cause +
                       ". Fix: " + fix + ".");
    }

    QuietErrors::QuietErrors()
    {
      H5Eget_auto2(H5E_DEFAULT, &function, &data);
      H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    }

    QuietErrors::~QuietErrors()
    {
      H5Eset_auto2(H5E_DEFAULT, function, data);
    }
  } // namespace Hdf5Record
} // namespace softgrasp

#include <cstdio>
#include <filesystem>
#include <hdf5.h>
#include <softgrasp/base/atomic_file.h>
#include <softgrasp/base/fatal_error.h>
#include <softgrasp/base/input_error.h>
#include <softgrasp/base/run_manifest.h>
#include <softgrasp/io/hdf5_record.h>
#include <stdexcept>

namespace softgrasp
{
  using namespace dealii;

  void Hdf5Record::write(const std::string                       &filename,
                         const std::function<void(HDF5::File &)> &fill)
  {
    RunManifest::note(filename);
    const std::string temporary = AtomicFile::temporary_name(filename);
    try
    {
      HDF5::File file(temporary, HDF5::File::FileAccessMode::create);
      fill(file);
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

  namespace
  {
    /// Closes an HDF5 identifier when it goes out of scope.
    struct Id
    {
      hid_t id;
      herr_t (*close)(hid_t);
      ~Id()
      {
        if (id >= 0)
          close(id);
      }
    };

    [[noreturn]] void fail(const std::string &what)
    {
      throw std::runtime_error(what);
    }

    /// @p object's attribute @p name, opened.
    hid_t open_attribute(hid_t              file,
                         const std::string &object,
                         const std::string &name)
    {
      const std::string path = object.empty() ? "/" : object;
      if (H5Aexists_by_name(file, path.c_str(), name.c_str(), H5P_DEFAULT) <= 0)
        fail("no attribute '" + name + "' on '" + path + "'");
      const hid_t attribute = H5Aopen_by_name(
          file, path.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
      if (attribute < 0)
        fail("the attribute '" + name + "' on '" + path + "' is unreadable");
      return attribute;
    }
  } // namespace

  Hdf5Record::Reader::Reader(const std::string &filename)
      : file(H5Fopen(filename.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT))
  {
    if (file < 0)
      fail("HDF5 cannot open it");
  }

  Hdf5Record::Reader::~Reader()
  {
    H5Fclose(file);
  }

  std::string
  Hdf5Record::Reader::string_attribute(const std::string &object,
                                       const std::string &name) const
  {
    const Id attribute{open_attribute(file, object, name), H5Aclose};
    const Id type{H5Aget_type(attribute.id), H5Tclose};
    if (H5Tget_class(type.id) != H5T_STRING)
      fail("the attribute '" + name + "' is not a string");
    if (H5Tis_variable_str(type.id) > 0)
    {
      char *value = nullptr;
      if (H5Aread(attribute.id, type.id, &value) < 0 || value == nullptr)
        fail("the attribute '" + name + "' is unreadable");
      std::string result(value);
      H5free_memory(value);
      return result;
    }
    std::string value(H5Tget_size(type.id), '\0');
    if (H5Aread(attribute.id, type.id, value.data()) < 0)
      fail("the attribute '" + name + "' is unreadable");
    return value.substr(0, value.find('\0'));
  }

  double Hdf5Record::Reader::number_attribute(const std::string &object,
                                              const std::string &name) const
  {
    const Id attribute{open_attribute(file, object, name), H5Aclose};
    double   value = 0;
    if (H5Aread(attribute.id, H5T_NATIVE_DOUBLE, &value) < 0)
      fail("the attribute '" + name + "' is not a number");
    return value;
  }

  std::vector<double> Hdf5Record::Reader::vector(const std::string &path) const
  {
    if (H5Lexists(file, path.c_str(), H5P_DEFAULT) <= 0)
      fail("no dataset '" + path + "'");
    const Id set{H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose};
    const Id space{H5Dget_space(set.id), H5Sclose};
    if (H5Sget_simple_extent_ndims(space.id) != 1)
      fail("the dataset '" + path + "' is not one-dimensional");
    std::vector<double> values(H5Sget_simple_extent_npoints(space.id));
    if (!values.empty() && H5Dread(set.id,
                                   H5T_NATIVE_DOUBLE,
                                   H5S_ALL,
                                   H5S_ALL,
                                   H5P_DEFAULT,
                                   values.data()) < 0)
      fail("the dataset '" + path + "' is unreadable");
    return values;
  }

  void Hdf5Record::read(const std::string                         &filename,
                        const std::string                         &fix,
                        const std::function<void(const Reader &)> &read)
  {
    std::string cause;
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
      catch (const std::exception &e)
      {
        cause = "cannot be read: " + error_message(e);
      }
    throw InputError("The file '" + filename + "' " + cause + ". Fix: " + fix +
                     ".");
  }

  void Hdf5Record::write_vector(HDF5::Group               &group,
                                const std::string         &name,
                                const std::vector<double> &values)
  {
    auto dataset = group.create_dataset<double>(
        name, {static_cast<hsize_t>(values.size())});
    if (!values.empty())
      dataset.write(values);
  }

} // namespace softgrasp

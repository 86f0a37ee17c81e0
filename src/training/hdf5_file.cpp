#include "hdf5_file.h"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// Owns one HDF5 identifier (dataspace, dataset, type, attribute) and closes it on scope exit.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

template <typename Scalar>
struct Hdf5Type;
template <>
struct Hdf5Type<float> {
  static hid_t file() { return H5T_IEEE_F32LE; }
  static hid_t memory() { return H5T_NATIVE_FLOAT; }
  static constexpr H5T_class_t kClass = H5T_FLOAT;
};
template <>
struct Hdf5Type<double> {
  static hid_t file() { return H5T_IEEE_F64LE; }
  static hid_t memory() { return H5T_NATIVE_DOUBLE; }
  static constexpr H5T_class_t kClass = H5T_FLOAT;
};
template <>
struct Hdf5Type<int> {
  static hid_t file() { return H5T_STD_I32LE; }
  static hid_t memory() { return H5T_NATIVE_INT; }
  static constexpr H5T_class_t kClass = H5T_INTEGER;
};

const char* className(H5T_class_t type_class) {
  switch (type_class) {
    case H5T_INTEGER:
      return "integer";
    case H5T_FLOAT:
      return "floating-point";
    case H5T_STRING:
      return "string";
    default:
      return "non-numeric";
  }
}

// A corrupted header could announce absurd sizes; refuse before trying to allocate them.
constexpr hsize_t kMaxElements = hsize_t{1} << 31;

// Files are written in HDF5 1.10's format (superblock version 3, version 2 object headers, the
// single-chunk index): every piece of metadata carries a checksum, and each dataset is one chunk
// with the Fletcher-32 filter, so HDF5 refuses a damaged byte anywhere before decoding it. That
// matters because HDF5 1.10.8 itself overruns buffers while decoding some damaged version-1
// headers (our fuzzer found one in an attribute's name); files without checksums are refused
// before HDF5 decodes anything but their superblock's first bytes.
constexpr unsigned kFirstChecksummedSuperblock = 2;
constexpr unsigned kChecksummedObjectHeader = 2;

// The superblock version byte that follows the HDF5 signature at the file's start, or -1 when the
// file does not start with the signature (we never write a user block before it).
int superblockVersion(const std::string& path) {
  static constexpr std::array<char, 8> kSignature = {'\x89', 'H',  'D',    'F',
                                                     '\r',   '\n', '\x1a', '\n'};
  std::array<char, 9> head{};
  std::ifstream file(path, std::ios::binary);
  if (!file.read(head.data(), head.size())) return -1;
  if (!std::equal(kSignature.begin(), kSignature.end(), head.begin())) return -1;
  return static_cast<unsigned char>(head[8]);
}

}  // namespace

void silenceHdf5ErrorPrinting() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

void Hdf5File::writeAtomically(const std::string& path,
                               const std::function<void(Hdf5File&)>& write) {
  // Same directory as the target, so the final rename is atomic (no cross-device move).
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  try {
    Hdf5File file = create(temporary, path);
    write(file);
    file.close();
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) throw Error(path + ": cannot replace the file: " + error.message());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

Hdf5File Hdf5File::create(const std::string& path, const std::string& label) {
  silenceHdf5ErrorPrinting();
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!access.valid() || H5Pset_libver_bounds(access.get(), H5F_LIBVER_V110, H5F_LIBVER_V110) < 0) {
    throw Error(label + ": cannot set up the HDF5 file format");
  }
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get());
  if (id < 0) {
    throw Error(label + ": cannot create the file (does its directory exist and is it writable?)");
  }
  return Hdf5File(id, label);
}

Hdf5File Hdf5File::openReadOnly(const std::string& path, const std::string& label) {
  silenceHdf5ErrorPrinting();
  if (H5Fis_hdf5(path.c_str()) <= 0) throw Error(label + ": truncated or not an HDF5 file");
  const int superblock = superblockVersion(path);
  if (superblock < static_cast<int>(kFirstChecksummedSuperblock)) {
    throw Error(
        label + ": an HDF5 file without metadata checksums (superblock version " +
        std::to_string(superblock) +
        "), which this package does not decode; a bundle written by release 0.4 or earlier "
        "can be converted with `h5repack --low=2 --high=2 -f FLET OLD NEW` (Debian's hdf5-tools)");
  }
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) throw Error(label + ": truncated or not an HDF5 file");
  Hdf5File file(id, label);
  file.checkObjectHeader("/");
  return file;
}

void Hdf5File::checkObjectHeader(const std::string& name) const {
  H5O_info_t info;
  if (H5Oget_info_by_name2(id_, name.c_str(), &info, H5O_INFO_HDR, H5P_DEFAULT) < 0) {
    fail("the header of " + name + " is damaged (its checksum does not match)");
  }
  if (info.hdr.version < kChecksummedObjectHeader) {
    fail("the header of " + name + " has no checksum (version " + std::to_string(info.hdr.version) +
         "): the file is damaged");
  }
}

Hdf5File::Hdf5File(Hdf5File&& other) noexcept
    : id_(std::exchange(other.id_, H5I_INVALID_HID)), label_(std::move(other.label_)) {}

Hdf5File::~Hdf5File() {
  if (id_ >= 0) H5Fclose(id_);
}

void Hdf5File::close() {
  if (id_ < 0) return;
  const bool flushed = H5Fflush(id_, H5F_SCOPE_GLOBAL) >= 0;
  const bool closed = H5Fclose(id_) >= 0;
  id_ = H5I_INVALID_HID;
  if (!flushed || !closed) fail("writing the file failed (is the disk full?)");
}

void Hdf5File::fail(const std::string& problem) const { throw Error(label_ + ": " + problem); }

void Hdf5File::createGroup(const std::string& name) {
  Handle group(H5Gcreate2(id_, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (!group.valid()) fail("cannot create group " + name);
}

bool Hdf5File::exists(const std::string& name) const {
  for (std::size_t slash = name.find('/');; slash = name.find('/', slash + 1)) {
    const std::string prefix = name.substr(0, slash);
    if (H5Lexists(id_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    checkObjectHeader(prefix);
    if (slash == std::string::npos) return true;
  }
}

template <typename Scalar>
void Hdf5File::write(const std::string& name, const Scalar* row_major, int rank,
                     const hsize_t* dims) {
  Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  if (!space.valid()) fail("cannot create the dataspace of dataset " + name);
  hsize_t elements = 1;
  for (int i = 0; i < rank; ++i) elements *= dims[i];
  // One chunk holding the whole dataset, checksummed (an empty dataset has no values to protect
  // and HDF5 refuses empty chunks).
  Handle creation(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (!creation.valid() || (elements > 0 && (H5Pset_chunk(creation.get(), rank, dims) < 0 ||
                                             H5Pset_fletcher32(creation.get()) < 0))) {
    fail("cannot set up the storage of dataset " + name);
  }
  Handle set(H5Dcreate2(id_, name.c_str(), Hdf5Type<Scalar>::file(), space.get(), H5P_DEFAULT,
                        creation.get(), H5P_DEFAULT),
             H5Dclose);
  if (!set.valid()) fail("cannot create dataset " + name);
  if (elements > 0 && H5Dwrite(set.get(), Hdf5Type<Scalar>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT,
                               row_major) < 0) {
    fail("cannot write dataset " + name);
  }
}

template <typename Scalar>
void Hdf5File::writeMatrix(const std::string& name, const Matrix<Scalar>& matrix) {
  const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row_major = matrix;
  const hsize_t dims[2] = {static_cast<hsize_t>(matrix.rows()),
                           static_cast<hsize_t>(matrix.cols())};
  write(name, row_major.data(), 2, dims);
}

template <typename Scalar>
void Hdf5File::writeVector(const std::string& name, const Vector<Scalar>& vector) {
  const hsize_t dims[1] = {static_cast<hsize_t>(vector.size())};
  write(name, vector.data(), 1, dims);
}

template <typename Scalar>
Hdf5File::Matrix<Scalar> Hdf5File::read(const std::string& name, int rank) const {
  // H5Dopen fails for a missing intermediate group too; check each level for a clear message.
  for (std::size_t slash = name.find('/');; slash = name.find('/', slash + 1)) {
    const std::string prefix = name.substr(0, slash);
    if (H5Lexists(id_, prefix.c_str(), H5P_DEFAULT) <= 0) {
      fail((slash == std::string::npos ? "dataset " : "group ") + prefix + " is missing");
    }
    checkObjectHeader(prefix);
    if (slash == std::string::npos) break;
  }
  Handle set(H5Dopen2(id_, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.valid()) fail(name + " is not a readable dataset");
  Handle space(H5Dget_space(set.get()), H5Sclose);
  Handle type(H5Dget_type(set.get()), H5Tclose);
  if (!space.valid() || !type.valid()) fail("cannot read dataset " + name);
  const int ndims = H5Sget_simple_extent_ndims(space.get());
  if (ndims != rank) {
    fail("dataset " + name + " has " + std::to_string(ndims) + " dimensions, expected " +
         std::to_string(rank));
  }
  const H5T_class_t stored = H5Tget_class(type.get());
  if (stored != Hdf5Type<Scalar>::kClass) {
    fail("dataset " + name + " holds " + className(stored) + " values, expected " +
         className(Hdf5Type<Scalar>::kClass));
  }
  hsize_t dims[2] = {1, 1};
  H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  if (dims[0] > kMaxElements || dims[1] > kMaxElements || dims[0] * dims[1] > kMaxElements) {
    fail("dataset " + name + " has an implausible size (the file is damaged)");
  }
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> row_major(
      static_cast<Eigen::Index>(dims[0]), static_cast<Eigen::Index>(dims[1]));
  if (row_major.size() > 0 && H5Dread(set.get(), Hdf5Type<Scalar>::memory(), H5S_ALL, H5S_ALL,
                                      H5P_DEFAULT, row_major.data()) < 0) {
    fail("cannot read dataset " + name + " (the file is truncated or damaged)");
  }
  return row_major;
}

template <typename Scalar>
Hdf5File::Matrix<Scalar> Hdf5File::readMatrix(const std::string& name) const {
  return read<Scalar>(name, 2);
}

template <typename Scalar>
Hdf5File::Vector<Scalar> Hdf5File::readVector(const std::string& name) const {
  return read<Scalar>(name, 1).col(0);
}

void Hdf5File::writeAttribute(const std::string& object, const std::string& name, double value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate_by_name(id_, object.c_str(), name.c_str(), H5T_IEEE_F64LE, space.get(),
                                     H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose);
  if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0) {
    fail("cannot write attribute " + name + " of " + object);
  }
}

void Hdf5File::writeAttribute(const std::string& object, const std::string& name,
                              std::int64_t value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate_by_name(id_, object.c_str(), name.c_str(), H5T_STD_I64LE, space.get(),
                                     H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose);
  if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_INT64, &value) < 0) {
    fail("cannot write attribute " + name + " of " + object);
  }
}

void Hdf5File::writeAttribute(const std::string& object, const std::string& name,
                              const std::string& value) {
  // Fixed-length, NUL-padded UTF-8: h5dump shows it as text; HDF5 types cannot have size 0.
  std::string buffer = value;
  buffer.resize(std::max<std::size_t>(1, value.size()), '\0');
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), buffer.size());
  H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate_by_name(id_, object.c_str(), name.c_str(), type.get(), space.get(),
                                     H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose);
  if (!attribute.valid() || H5Awrite(attribute.get(), type.get(), buffer.data()) < 0) {
    fail("cannot write attribute " + name + " of " + object);
  }
}

bool Hdf5File::hasAttribute(const std::string& object, const std::string& name) const {
  checkObjectHeader(object);
  return H5Aexists_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

std::vector<std::string> Hdf5File::attributeNames(const std::string& object) const {
  checkObjectHeader(object);
  std::vector<std::string> names;
  H5A_operator2_t collect = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->push_back(name);
    return 0;
  };
  hsize_t index = 0;
  if (H5Aiterate_by_name(id_, object.c_str(), H5_INDEX_NAME, H5_ITER_INC, &index, collect, &names,
                         H5P_DEFAULT) < 0) {
    fail("cannot list the attributes of " + object);
  }
  return names;
}

hid_t Hdf5File::openAttribute(const std::string& object, const std::string& name) const {
  const std::string where = object == "/" ? name : object + "/" + name;
  if (!hasAttribute(object, name)) fail("attribute " + where + " is missing");
  const hid_t attribute =
      H5Aopen_by_name(id_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (attribute < 0) fail("cannot open attribute " + where);
  Handle space(H5Aget_space(attribute), H5Sclose);
  if (H5Sget_simple_extent_npoints(space.get()) != 1) {
    H5Aclose(attribute);
    fail("attribute " + where + " is not a single value");
  }
  return attribute;
}

double Hdf5File::readDoubleAttribute(const std::string& object, const std::string& name) const {
  Handle attribute(openAttribute(object, name), H5Aclose);
  Handle type(H5Aget_type(attribute.get()), H5Tclose);
  double value = 0.0;
  if (H5Tget_class(type.get()) != H5T_FLOAT ||
      H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0) {
    fail("attribute " + name + " of " + object + " is not a readable floating-point number");
  }
  return value;
}

std::int64_t Hdf5File::readIntegerAttribute(const std::string& object,
                                            const std::string& name) const {
  Handle attribute(openAttribute(object, name), H5Aclose);
  Handle type(H5Aget_type(attribute.get()), H5Tclose);
  std::int64_t value = 0;
  if (H5Tget_class(type.get()) != H5T_INTEGER ||
      H5Aread(attribute.get(), H5T_NATIVE_INT64, &value) < 0) {
    fail("attribute " + name + " of " + object + " is not a readable integer");
  }
  return value;
}

std::string Hdf5File::readStringAttribute(const std::string& object,
                                          const std::string& name) const {
  Handle attribute(openAttribute(object, name), H5Aclose);
  Handle type(H5Aget_type(attribute.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING) {
    fail("attribute " + name + " of " + object + " is not a string");
  }
  // The stored type itself as memory type: HDF5 refuses to convert between character sets, and
  // a NUL-terminated memory type of the same size would cut the last character.
  Handle memory(H5Tcopy(type.get()), H5Tclose);
  if (H5Tis_variable_str(type.get()) > 0) {  // as h5py writes strings by default
    char* text = nullptr;
    if (H5Aread(attribute.get(), memory.get(), &text) < 0 || text == nullptr) {
      fail("cannot read attribute " + name + " of " + object);
    }
    std::string value(text);
    H5free_memory(text);
    return value;
  }
  const std::size_t size = H5Tget_size(type.get());
  std::vector<char> buffer(size + 1, '\0');
  if (H5Aread(attribute.get(), memory.get(), buffer.data()) < 0) {
    fail("cannot read attribute " + name + " of " + object);
  }
  return std::string(buffer.data());  // up to the first NUL (padding)
}

#define VDC_INSTANTIATE_HDF5_IO(Scalar)                                                     \
  template void Hdf5File::writeMatrix<Scalar>(const std::string&, const Matrix<Scalar>&);   \
  template void Hdf5File::writeVector<Scalar>(const std::string&, const Vector<Scalar>&);   \
  template Hdf5File::Matrix<Scalar> Hdf5File::readMatrix<Scalar>(const std::string&) const; \
  template Hdf5File::Vector<Scalar> Hdf5File::readVector<Scalar>(const std::string&) const;
VDC_INSTANTIATE_HDF5_IO(float)
VDC_INSTANTIATE_HDF5_IO(double)
VDC_INSTANTIATE_HDF5_IO(int)
#undef VDC_INSTANTIATE_HDF5_IO

}  // namespace vdc

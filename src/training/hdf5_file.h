#pragma once

// Private to the core libraries: a thin RAII layer over the HDF5 C API for the model bundle (and
// the recognition module's object memory file).
// Matrices are stored as row-major 2-D datasets (h5py and h5dump show them as rows x columns,
// like Eigen), vectors as 1-D datasets. Every failure throws vdc::Error prefixed with the file's
// label, so the caller's message names the file.

#include <hdf5.h>

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace vdc {

// HDF5 prints its whole error stack to stderr by default; a bad file must give our one line only.
void silenceHdf5ErrorPrinting();

class Hdf5File {
 public:
  template <typename Scalar>
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  template <typename Scalar>
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;

  // `label` prefixes every error message (normally the path the user gave).
  static Hdf5File create(const std::string& path, const std::string& label);
  static Hdf5File openReadOnly(const std::string& path, const std::string& label);
  // Creates `path` by `write` on a temporary file beside it, renamed over it once closed: a
  // crash or an error mid-write leaves the previous file as it was (the temporary is removed).
  // Errors are labelled with `path`.
  static void writeAtomically(const std::string& path, const std::function<void(Hdf5File&)>& write);

  Hdf5File(Hdf5File&& other) noexcept;
  Hdf5File& operator=(Hdf5File&&) = delete;
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;
  ~Hdf5File();

  // Flushes and closes; throws if HDF5 reports an error (e.g. the disk is full).
  void close();

  void createGroup(const std::string& name);
  // Whether a group or dataset of that path exists (each level checked, headers verified).
  bool exists(const std::string& name) const;

  // Scalar: float, double or int (stored as IEEE 32/64-bit or 32-bit little-endian integers).
  template <typename Scalar>
  void writeMatrix(const std::string& name, const Matrix<Scalar>& matrix);
  template <typename Scalar>
  void writeVector(const std::string& name, const Vector<Scalar>& vector);
  // Reads a dataset of any size; throws if it is missing, has another rank or number class.
  template <typename Scalar>
  Matrix<Scalar> readMatrix(const std::string& name) const;
  template <typename Scalar>
  Vector<Scalar> readVector(const std::string& name) const;

  // Attributes of the object (group or dataset) at `object`, "/" for the root.
  void writeAttribute(const std::string& object, const std::string& name, double value);
  void writeAttribute(const std::string& object, const std::string& name, std::int64_t value);
  void writeAttribute(const std::string& object, const std::string& name, const std::string& value);
  bool hasAttribute(const std::string& object, const std::string& name) const;
  // The names of the object's attributes (files that key values by name, e.g. per model).
  std::vector<std::string> attributeNames(const std::string& object) const;
  // Throw if missing or of the other number class (integer vs floating point) or not a string.
  double readDoubleAttribute(const std::string& object, const std::string& name) const;
  std::int64_t readIntegerAttribute(const std::string& object, const std::string& name) const;
  std::string readStringAttribute(const std::string& object, const std::string& name) const;

 private:
  Hdf5File(hid_t id, std::string label) : id_(id), label_(std::move(label)) {}
  [[noreturn]] void fail(const std::string& problem) const;
  // Throws unless the object's header is intact and checksummed (see hdf5_file.cpp).
  void checkObjectHeader(const std::string& name) const;
  hid_t openAttribute(const std::string& object, const std::string& name) const;
  template <typename Scalar>
  void write(const std::string& name, const Scalar* row_major, int rank, const hsize_t* dims);
  template <typename Scalar>
  Matrix<Scalar> read(const std::string& name, int rank) const;

  hid_t id_ = H5I_INVALID_HID;
  std::string label_;
};

}  // namespace vdc

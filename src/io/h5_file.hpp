// Thin RAII layer over the HDF5 C API: just what the result schema needs (groups, 1-D double
// datasets, scalar and string attributes). HDF5's own error printing is switched off; every
// failed write throws WriteError (file name and reason, e.g. "no space left on device"), every
// failed read std::runtime_error. A file being written must end with close(), which flushes and
// reports what the flush could not write; the destructor closes silently (on error paths).
#pragma once
#include <cstdint>
#include <hdf5.h>

#include "core/vec2.hpp"
#include <string>
#include <vector>

namespace granrepro {

class H5Object {
public:
    H5Object() = default;
    H5Object(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
    H5Object(const H5Object&) = delete;
    H5Object& operator=(const H5Object&) = delete;
    H5Object(H5Object&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
    ~H5Object() { if (id_ >= 0 && close_) close_(id_); }
    hid_t id() const { return id_; }

    H5Object group(const std::string& name) const;     // create
    H5Object open_group(const std::string& name) const;
    void attr(const std::string& name, double v) const;
    void attr(const std::string& name, long v) const;
    void attr(const std::string& name, const std::string& v) const;
    void attr(const std::string& name, const std::vector<double>& v) const;
    // A 1-D double dataset with a "unit" attribute (and optional description).
    void dataset(const std::string& name, const std::vector<double>& v, const std::string& unit,
                 const std::string& description = {}) const;
    void bytes(const std::string& name, const std::vector<unsigned char>& v) const { array(name, v); }
    // A 1-D uint8 dataset of text (e.g. JSON), deflate-compressed (level 9, chunked) where the
    // HDF5 library has the filter; read back with read_bytes.
    void compressed_text(const std::string& name, const std::string& text) const;
    // A 1-D dataset stored bit for bit (checkpoints). T: double, int32, uint8, uint32, uint64.
    template <class T>
    void array(const std::string& name, const std::vector<T>& v) const;
    void attr_u64(const std::string& name, std::uint64_t v) const;

    std::vector<double> read_dataset(const std::string& name) const { return read_array<double>(name); }
    std::vector<unsigned char> read_bytes(const std::string& name) const { return read_array<unsigned char>(name); }
    // What compressed_text wrote; refused (std::runtime_error) past max_bytes, before it is read.
    std::string read_text(const std::string& name, std::size_t max_bytes) const;
    // A scalar string attribute (fixed or variable length) of at most kMaxTextFileBytes; any other
    // attribute (an array, a number) is refused with std::runtime_error naming it. The number
    // readers likewise refuse anything but one number.
    std::string read_string_attr(const std::string& name) const;
    double read_double_attr(const std::string& name) const;
    long read_long_attr(const std::string& name) const;
    std::uint64_t read_u64_attr(const std::string& name) const;
    template <class T>
    std::vector<T> read_array(const std::string& name) const;
    bool has(const std::string& name) const; // a link (group or dataset) of that name exists
    bool has_attr(const std::string& name) const;
    // Names of the links in this group (H5_INDEX_CRT_ORDER: in creation order, where it was tracked).
    std::vector<std::string> children(H5_index_t order = H5_INDEX_NAME) const;
    std::vector<std::string> attribute_names() const;
    std::size_t dataset_size(const std::string& name) const; // number of elements
    // Copies the object `name` (group or dataset, with its attributes) into `dst` under the same name.
    void copy_to(const std::string& name, const H5Object& dst) const;
    // Copies attribute `name` to `dst` (strings, integers and doubles, as the result schema uses).
    void copy_attr_to(const std::string& name, const H5Object& dst) const;

    // Vectors as two datasets <name>_x and <name>_y, bit for bit.
    void vec2_array(const std::string& name, const std::vector<Vec2>& v) const;
    std::vector<Vec2> read_vec2_array(const std::string& name) const;
    // Attributes "schema" and "schema_version" name the layout of a group.
    void stamp_schema(const std::string& schema, long version) const;
    // Throws std::runtime_error unless the group carries exactly this schema and version.
    void require_schema(const std::string& schema, long version) const;

protected:
    hid_t id_ = -1;

private:
    herr_t (*close_)(hid_t) = nullptr;
};

class H5File : public H5Object {
public:
    static H5File create(const std::string& path); // truncates
    // Read-only; a symlink or a non-regular file is refused with InputError (core/untrusted_file.hpp).
    static H5File open(const std::string& path);
    // Flushes and closes; throws WriteError if the data did not reach the file.
    void close();

private:
    using H5Object::H5Object;
};

} // namespace granrepro

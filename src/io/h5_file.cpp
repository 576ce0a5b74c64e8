#include "io/h5_file.hpp"

#include <algorithm>

#include <cctype>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "core/untrusted_file.hpp"

#include "io/write_error.hpp"

namespace granrepro {

namespace {
// HDF5 prints its error stack to stderr by default (a hundred lines of HDF5-DIAG for a full disk);
// we turn a failure into one exception instead. Called before every file is created or opened
// (in a thread-safe HDF5 the setting is per thread).
void silence_hdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

struct Reason {
    std::string text;
    bool system = false; // text is the operating system's error (strerror)
};

herr_t innermost(unsigned n, const H5E_error2_t* e, void* data) {
    auto* reason = static_cast<Reason*>(data);
    const std::string desc = e->desc ? e->desc : "";
    // The sec2 driver reports the system error as "..., error message = 'No space left on device', ...".
    const auto at = desc.find("error message = '");
    if (at != std::string::npos) {
        const auto b = at + 17, end = desc.find('\'', b);
        std::string msg = desc.substr(b, end == std::string::npos ? std::string::npos : end - b);
        if (msg.size() > 1 && std::isupper(static_cast<unsigned char>(msg[0])) && std::islower(static_cast<unsigned char>(msg[1])))
            msg[0] = char(std::tolower(static_cast<unsigned char>(msg[0])));
        *reason = {msg, true};
        return 1; // stop: the system's reason is the most useful one
    }
    if (n == 0) reason->text = desc;
    return 0;
}

// The reason of the failure HDF5 just reported (read before any other HDF5 call clears it).
Reason hdf5_reason() {
    Reason reason;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, innermost, &reason);
    if (reason.text.empty()) reason.text = "unknown HDF5 error";
    return reason;
}

std::string file_name(hid_t obj) {
    const ssize_t n = obj >= 0 ? H5Fget_name(obj, nullptr, 0) : -1;
    if (n <= 0) return "an HDF5 file";
    std::string s(std::size_t(n) + 1, '\0');
    H5Fget_name(obj, s.data(), s.size());
    s.resize(std::size_t(n));
    return s;
}

// A failed write: WriteError naming the file (`file`, or else the one `obj` is in) and the reason
// ("no space left on device", or HDF5's own words and what we asked of it).
WriteError write_error(const std::string& what, hid_t obj, const std::string& file = {}) {
    const Reason r = hdf5_reason(); // first: file_name() is an HDF5 call too
    return WriteError(file.empty() ? file_name(obj) : file,
                      r.system ? r.text : "HDF5 could not " + what + " (" + r.text + ")");
}
template <class Id> // hid_t or herr_t
Id wcheck(Id id, hid_t obj, const std::string& what) {
    if (id < 0) throw write_error(what, obj);
    return id;
}
template <class Id>
Id check(Id id, const std::string& what) {
    if (id < 0) throw std::runtime_error("HDF5: " + what + ": " + hdf5_reason().text);
    return id;
}

// Links and attributes keep the order they were created in (tables' columns, the root's
// provenance), for readers that iterate by creation order (h5py: track_order).
constexpr unsigned kCreationOrder = H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED;
H5Object ordered(hid_t plist_class, bool links) {
    H5Object p(H5Pcreate(plist_class), &H5Pclose);
    if (links) H5Pset_link_creation_order(p.id(), kCreationOrder);
    H5Pset_attr_creation_order(p.id(), kCreationOrder);
    return p;
}

void write_attr(hid_t obj, const std::string& name, hid_t type, hid_t space, const void* data) {
    const hid_t a = wcheck(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), obj,
                           "create attribute " + name);
    const H5Object attr(a, &H5Aclose);
    wcheck(H5Awrite(a, type, data), obj, "write attribute " + name);
}
// Data spaces and types are only memory; their creation fails only when memory runs out.
H5Object scalar_space() { return {check(H5Screate(H5S_SCALAR), "data space"), &H5Sclose}; }
H5Object simple_space(hsize_t n) { return {check(H5Screate_simple(1, &n, nullptr), "data space"), &H5Sclose}; }

// A 1-D dataset of n elements of file type `file_type`, written from `data` (memory type `mem_type`).
H5Object write_dataset(hid_t obj, const std::string& name, hid_t file_type, hid_t mem_type, hsize_t n,
                       const void* data) {
    const H5Object s = simple_space(n);
    H5Object d(wcheck(H5Dcreate2(obj, name.c_str(), file_type, s.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), obj,
                      "create dataset " + name),
               &H5Dclose);
    if (n) wcheck(H5Dwrite(d.id(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), obj, "write dataset " + name);
    return d;
}

template <class T>
hid_t native_type();
template <> hid_t native_type<double>() { return H5T_NATIVE_DOUBLE; }
template <> hid_t native_type<long>() { return H5T_NATIVE_LONG; }
template <> hid_t native_type<std::int32_t>() { return H5T_NATIVE_INT32; }
template <> hid_t native_type<std::uint8_t>() { return H5T_NATIVE_UINT8; }
template <> hid_t native_type<std::uint32_t>() { return H5T_NATIVE_UINT32; }
template <> hid_t native_type<std::uint64_t>() { return H5T_NATIVE_UINT64; }

// An attribute read from a results folder is untrusted: its dataspace and type are checked before
// a value is read into a buffer sized for one (an array read there overflowed the heap).
H5Object open_single_attr(hid_t obj, const std::string& name) {
    H5Object a(check(H5Aopen(obj, name.c_str(), H5P_DEFAULT), "open attr " + name), &H5Aclose);
    const H5Object sp(check(H5Aget_space(a.id()), "attr space " + name), &H5Sclose);
    if (H5Sget_simple_extent_npoints(sp.id()) != 1 || H5Sget_simple_extent_type(sp.id()) == H5S_NULL)
        throw std::runtime_error("attribute " + name + " holds " + std::to_string(H5Sget_simple_extent_npoints(sp.id())) +
                                 " values, not one");
    return a;
}

template <class T>
T read_scalar_attr(hid_t obj, const std::string& name) {
    const H5Object a = open_single_attr(obj, name);
    const H5Object t(check(H5Aget_type(a.id()), "attr type " + name), &H5Tclose);
    if (const H5T_class_t c = H5Tget_class(t.id()); c != H5T_INTEGER && c != H5T_FLOAT)
        throw std::runtime_error("attribute " + name + " is not a number");
    T v = 0;
    check(H5Aread(a.id(), native_type<T>(), &v), "read attr " + name);
    return v;
}

// The names of the n links or attributes of obj, in `order`; get_name is H5Lget_name_by_idx or
// H5Aget_name_by_idx (one signature).
using NameByIndex = ssize_t (*)(hid_t, const char*, H5_index_t, H5_iter_order_t, hsize_t, char*, size_t, hid_t);
std::vector<std::string> names_by_index(hid_t obj, hsize_t n, NameByIndex get_name, H5_index_t order,
                                        const std::string& what) {
    std::vector<std::string> names;
    for (hsize_t i = 0; i < n; ++i) {
        const ssize_t len = get_name(obj, ".", order, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
        check(herr_t(len < 0 ? -1 : 0), what);
        std::string name(std::size_t(len) + 1, '\0');
        get_name(obj, ".", order, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT);
        name.resize(std::size_t(len));
        names.push_back(name);
    }
    return names;
}
} // namespace

H5File H5File::create(const std::string& path) {
    silence_hdf5();
    const H5Object fcpl = ordered(H5P_FILE_CREATE, true); // links and attributes keep their creation order
    const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.id(), H5P_DEFAULT);
    if (id < 0) throw write_error("create the file", id, path);
    return H5File(id, &H5Fclose);
}

H5File H5File::open(const std::string& path) {
    // HDF5 opens by name and would follow a symlink or block on a FIFO: every file opened here is
    // read from a results folder or a checkpoint, so only a regular file is opened.
    require_regular_file(path, "HDF5 file");
    silence_hdf5();
    return H5File(check(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "open " + path), &H5Fclose);
}

void H5File::close() {
    if (id_ < 0) return;
    const hid_t id = id_;
    const std::string name = file_name(id);
    id_ = -1; // a failed close is not retried by the destructor
    if (H5Fflush(id, H5F_SCOPE_GLOBAL) < 0) {
        const WriteError e = write_error("flush the file", id, name);
        H5Fclose(id);
        throw e;
    }
    if (H5Fclose(id) < 0) throw write_error("close the file", id, name);
}

H5Object H5Object::group(const std::string& name) const {
    const H5Object gcpl = ordered(H5P_GROUP_CREATE, true);
    return {wcheck(H5Gcreate2(id_, name.c_str(), H5P_DEFAULT, gcpl.id(), H5P_DEFAULT), id_, "create group " + name),
            &H5Gclose};
}

H5Object H5Object::open_group(const std::string& name) const {
    return {check(H5Gopen2(id_, name.c_str(), H5P_DEFAULT), "open group " + name), &H5Gclose};
}

void H5Object::attr(const std::string& name, double v) const {
    write_attr(id_, name, H5T_NATIVE_DOUBLE, scalar_space().id(), &v);
}

void H5Object::attr(const std::string& name, long v) const {
    write_attr(id_, name, H5T_NATIVE_LONG, scalar_space().id(), &v);
}

void H5Object::attr_u64(const std::string& name, std::uint64_t v) const {
    write_attr(id_, name, H5T_NATIVE_UINT64, scalar_space().id(), &v);
}

void H5Object::attr(const std::string& name, const std::string& v) const {
    const H5Object t(check(H5Tcopy(H5T_C_S1), "string type"), &H5Tclose);
    check(H5Tset_size(t.id(), v.empty() ? 1 : v.size()), "string type");
    check(H5Tset_cset(t.id(), H5T_CSET_UTF8), "string type");
    const std::string padded = v.empty() ? std::string(1, '\0') : v;
    write_attr(id_, name, t.id(), scalar_space().id(), padded.data());
}

void H5Object::attr(const std::string& name, const std::vector<double>& v) const {
    write_attr(id_, name, H5T_NATIVE_DOUBLE, simple_space(v.size()).id(), v.data());
}

void H5Object::dataset(const std::string& name, const std::vector<double>& v,
                       const std::string& unit, const std::string& description) const {
    const H5Object ds = write_dataset(id_, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, v.size(), v.data());
    ds.attr("unit", unit);
    if (!description.empty()) ds.attr("description", description);
}

void H5Object::compressed_text(const std::string& name, const std::string& text) const {
    const hsize_t n = text.size();
    const H5Object space = simple_space(n);
    const H5Object dcpl(check(H5Pcreate(H5P_DATASET_CREATE), "property list"), &H5Pclose);
    if (n > 0 && H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0) {
        const hsize_t chunk = std::min<hsize_t>(n, hsize_t(1) << 20);
        check(H5Pset_chunk(dcpl.id(), 1, &chunk), "chunk " + name);
        check(H5Pset_deflate(dcpl.id(), 9), "deflate " + name);
    }
    const H5Object d(wcheck(H5Dcreate2(id_, name.c_str(), H5T_STD_U8LE, space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT),
                            id_, "create dataset " + name),
                     &H5Dclose);
    if (n) wcheck(H5Dwrite(d.id(), H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()), id_, "write dataset " + name);
}

template <class T>
void H5Object::array(const std::string& name, const std::vector<T>& v) const {
    write_dataset(id_, name, native_type<T>(), native_type<T>(), v.size(), v.data());
}

template <class T>
std::vector<T> H5Object::read_array(const std::string& name) const {
    H5Object d(check(H5Dopen2(id_, name.c_str(), H5P_DEFAULT), "open " + name), &H5Dclose);
    H5Object s(H5Dget_space(d.id()), &H5Sclose);
    const hssize_t n = H5Sget_simple_extent_npoints(s.id());
    std::vector<T> v(static_cast<std::size_t>(n));
    if (n) check(H5Dread(d.id(), native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), "read " + name);
    return v;
}

template void H5Object::array(const std::string&, const std::vector<double>&) const;
template void H5Object::array(const std::string&, const std::vector<std::int32_t>&) const;
template void H5Object::array(const std::string&, const std::vector<std::uint8_t>&) const;
template void H5Object::array(const std::string&, const std::vector<std::uint32_t>&) const;
template void H5Object::array(const std::string&, const std::vector<std::uint64_t>&) const;
template std::vector<double> H5Object::read_array(const std::string&) const;
template std::vector<std::int32_t> H5Object::read_array(const std::string&) const;
template std::vector<std::uint8_t> H5Object::read_array(const std::string&) const;
template std::vector<std::uint32_t> H5Object::read_array(const std::string&) const;
template std::vector<std::uint64_t> H5Object::read_array(const std::string&) const;
template std::vector<long> H5Object::read_array(const std::string&) const;

long H5Object::read_long_attr(const std::string& name) const { return read_scalar_attr<long>(id_, name); }
std::uint64_t H5Object::read_u64_attr(const std::string& name) const {
    return read_scalar_attr<std::uint64_t>(id_, name);
}
double H5Object::read_double_attr(const std::string& name) const { return read_scalar_attr<double>(id_, name); }

std::string H5Object::read_text(const std::string& name, std::size_t max_bytes) const {
    // Sized before it is read: a few kB of deflated zeros expand to any size.
    if (dataset_size(name) > max_bytes)
        throw std::runtime_error(name + " is larger than its cap of " + std::to_string(max_bytes >> 20) + " MiB (docs/schema.md)");
    const std::vector<unsigned char> bytes = read_bytes(name);
    return {bytes.begin(), bytes.end()};
}

// A scalar string, fixed-length (what we write) or variable-length (h5py's default), of at most
// kMaxTextFileBytes; anything else (an array of strings, a number, a huge string) is refused.
std::string H5Object::read_string_attr(const std::string& name) const {
    const H5Object a = open_single_attr(id_, name);
    const H5Object t(check(H5Aget_type(a.id()), "attr type " + name), &H5Tclose);
    if (H5Tget_class(t.id()) != H5T_STRING) throw std::runtime_error("attribute " + name + " is not a string");
    const std::string too_large = "attribute " + name + " is larger than its cap of " +
                                  std::to_string(kMaxTextFileBytes >> 20) + " MiB (docs/schema.md)";
    if (check(H5Tis_variable_str(t.id()), "attr type " + name) > 0) {
        const H5Object mem(check(H5Tcopy(H5T_C_S1), "string type"), &H5Tclose);
        check(H5Tset_size(mem.id(), H5T_VARIABLE), "string type");
        check(H5Tset_cset(mem.id(), H5Tget_cset(t.id())), "string type");
        char* p = nullptr;
        check(H5Aread(a.id(), mem.id(), &p), "read attr " + name);
        const std::unique_ptr<char, herr_t (*)(void*)> owned(p, &H5free_memory);
        if (!p) return {};
        const std::size_t n = ::strnlen(p, kMaxTextFileBytes + 1);
        if (n > kMaxTextFileBytes) throw std::runtime_error(too_large);
        return {p, n};
    }
    const std::size_t size = H5Tget_size(t.id());
    if (size > kMaxTextFileBytes) throw std::runtime_error(too_large);
    std::string s(size, '\0');
    check(H5Aread(a.id(), t.id(), s.data()), "read attr " + name);
    while (!s.empty() && s.back() == '\0') s.pop_back();
    return s;
}

bool H5Object::has(const std::string& name) const { return H5Lexists(id_, name.c_str(), H5P_DEFAULT) > 0; }
bool H5Object::has_attr(const std::string& name) const { return H5Aexists(id_, name.c_str()) > 0; }

std::vector<std::string> H5Object::children(H5_index_t order) const {
    H5G_info_t info;
    check(H5Gget_info(id_, &info), "group info");
    return names_by_index(id_, info.nlinks, &H5Lget_name_by_idx, order, "link name");
}

std::vector<std::string> H5Object::attribute_names() const {
    H5O_info_t info;
    check(H5Oget_info2(id_, &info, H5O_INFO_NUM_ATTRS), "object info");
    return names_by_index(id_, info.num_attrs, &H5Aget_name_by_idx, H5_INDEX_NAME, "attribute name");
}

std::size_t H5Object::dataset_size(const std::string& name) const {
    H5Object d(check(H5Dopen2(id_, name.c_str(), H5P_DEFAULT), "open " + name), &H5Dclose);
    H5Object sp(H5Dget_space(d.id()), &H5Sclose);
    return std::size_t(H5Sget_simple_extent_npoints(sp.id()));
}

void H5Object::copy_to(const std::string& name, const H5Object& dst) const {
    wcheck(H5Ocopy(id_, name.c_str(), dst.id(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), dst.id(), "copy " + name);
}

void H5Object::copy_attr_to(const std::string& name, const H5Object& dst) const {
    H5Object a(check(H5Aopen(id_, name.c_str(), H5P_DEFAULT), "open attr " + name), &H5Aclose);
    H5Object t(H5Aget_type(a.id()), &H5Tclose);
    switch (H5Tget_class(t.id())) {
    case H5T_STRING: dst.attr(name, read_string_attr(name)); break;
    case H5T_INTEGER:
        if (H5Tget_sign(t.id()) == H5T_SGN_NONE && H5Tget_size(t.id()) == 8) dst.attr_u64(name, read_u64_attr(name));
        else dst.attr(name, read_long_attr(name));
        break;
    case H5T_FLOAT: {
        H5Object sp(H5Aget_space(a.id()), &H5Sclose);
        std::vector<double> v(std::size_t(H5Sget_simple_extent_npoints(sp.id())));
        check(H5Aread(a.id(), H5T_NATIVE_DOUBLE, v.data()), "read attr " + name);
        if (v.size() == 1 && H5Sget_simple_extent_type(sp.id()) == H5S_SCALAR) dst.attr(name, v[0]);
        else dst.attr(name, v);
        break;
    }
    default: throw std::runtime_error("attribute " + name + ": unsupported type");
    }
}

void H5Object::vec2_array(const std::string& name, const std::vector<Vec2>& v) const {
    std::vector<double> x(v.size()), y(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
        x[i] = v[i].x;
        y[i] = v[i].y;
    }
    array(name + "_x", x);
    array(name + "_y", y);
}

std::vector<Vec2> H5Object::read_vec2_array(const std::string& name) const {
    const auto x = read_array<double>(name + "_x"), y = read_array<double>(name + "_y");
    if (x.size() != y.size()) throw std::runtime_error("HDF5: " + name + "_x and " + name + "_y differ in length");
    std::vector<Vec2> v(x.size());
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = {x[i], y[i]};
    return v;
}

void H5Object::stamp_schema(const std::string& schema, long version) const {
    attr("schema", schema);
    attr("schema_version", version);
}

void H5Object::require_schema(const std::string& schema, long want) const {
    std::string found;
    try {
        found = read_string_attr("schema");
    } catch (const std::exception&) {
    }
    if (found != schema) throw std::runtime_error("not a " + schema + " group (schema attribute: '" + found + "')");
    const long version = read_long_attr("schema_version");
    if (version != want)
        throw std::runtime_error(schema + ": unsupported schema_version " + std::to_string(version) + " (this build reads " +
                                 std::to_string(want) + ")");
}

} // namespace granrepro

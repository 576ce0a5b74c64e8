#include "io/h5_file.hpp"

#include <stdexcept>

namespace granrepro {

namespace {
hid_t check(hid_t id, const std::string& what) {
    if (id < 0) throw std::runtime_error("HDF5: " + what);
    return id;
}
void check(herr_t e, const std::string& what) {
    if (e < 0) throw std::runtime_error("HDF5: " + what);
}
} // namespace

namespace {
// Links and attributes keep the order they were created in (tables' columns, the root's
// provenance), for readers that iterate by creation order (h5py: track_order).
constexpr unsigned kCreationOrder = H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED;
H5Object ordered(hid_t plist_class, bool links) {
    H5Object p(H5Pcreate(plist_class), &H5Pclose);
    if (links) H5Pset_link_creation_order(p.id(), kCreationOrder);
    H5Pset_attr_creation_order(p.id(), kCreationOrder);
    return p;
}
} // namespace

H5File H5File::create(const std::string& path) {
    const H5Object fcpl = ordered(H5P_FILE_CREATE, true);
    return H5File(check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.id(), H5P_DEFAULT), "create " + path), &H5Fclose);
}

H5File H5File::open(const std::string& path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return H5File(check(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), "open " + path), &H5Fclose);
}

H5Object H5Object::group(const std::string& name) const {
    const H5Object gcpl = ordered(H5P_GROUP_CREATE, true);
    return {check(H5Gcreate2(id_, name.c_str(), H5P_DEFAULT, gcpl.id(), H5P_DEFAULT), "group " + name), &H5Gclose};
}

H5Object H5Object::open_group(const std::string& name) const {
    return {check(H5Gopen2(id_, name.c_str(), H5P_DEFAULT), "open group " + name), &H5Gclose};
}

namespace {
void write_attr(hid_t obj, const std::string& name, hid_t type, hid_t space, const void* data) {
    const hid_t a = check(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), "attr " + name);
    const herr_t e = H5Awrite(a, type, data);
    H5Aclose(a);
    check(e, "write attr " + name);
}
} // namespace

void H5Object::attr(const std::string& name, double v) const {
    const hid_t s = H5Screate(H5S_SCALAR);
    write_attr(id_, name, H5T_NATIVE_DOUBLE, s, &v);
    H5Sclose(s);
}

void H5Object::attr(const std::string& name, long v) const {
    const hid_t s = H5Screate(H5S_SCALAR);
    write_attr(id_, name, H5T_NATIVE_LONG, s, &v);
    H5Sclose(s);
}

void H5Object::attr(const std::string& name, const std::string& v) const {
    const hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, v.empty() ? 1 : v.size());
    H5Tset_cset(t, H5T_CSET_UTF8);
    const hid_t s = H5Screate(H5S_SCALAR);
    const std::string padded = v.empty() ? std::string(1, '\0') : v;
    write_attr(id_, name, t, s, padded.data());
    H5Sclose(s);
    H5Tclose(t);
}

void H5Object::attr(const std::string& name, const std::vector<double>& v) const {
    const hsize_t n = v.size();
    const hid_t s = H5Screate_simple(1, &n, nullptr);
    write_attr(id_, name, H5T_NATIVE_DOUBLE, s, v.data());
    H5Sclose(s);
}

void H5Object::dataset(const std::string& name, const std::vector<double>& v,
                       const std::string& unit, const std::string& description) const {
    const hsize_t n = v.size();
    const hid_t s = H5Screate_simple(1, &n, nullptr);
    const H5Object dcpl = ordered(H5P_DATASET_CREATE, false);
    const hid_t d = check(H5Dcreate2(id_, name.c_str(), H5T_IEEE_F64LE, s, H5P_DEFAULT, dcpl.id(), H5P_DEFAULT),
                          "dataset " + name);
    const herr_t e = n ? H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) : 0;
    H5Sclose(s);
    H5Object ds(d, &H5Dclose);
    check(e, "write " + name);
    ds.attr("unit", unit);
    if (!description.empty()) ds.attr("description", description);
}

void H5Object::bytes(const std::string& name, const std::vector<unsigned char>& v) const {
    const hsize_t n = v.size();
    const hid_t s = H5Screate_simple(1, &n, nullptr);
    const hid_t d = check(H5Dcreate2(id_, name.c_str(), H5T_NATIVE_UCHAR, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                          "dataset " + name);
    const herr_t e = n ? H5Dwrite(d, H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) : 0;
    H5Sclose(s);
    H5Dclose(d);
    check(e, "write " + name);
}

namespace {
template <class T>
hid_t native_type();
template <> hid_t native_type<double>() { return H5T_NATIVE_DOUBLE; }
template <> hid_t native_type<std::int32_t>() { return H5T_NATIVE_INT32; }
template <> hid_t native_type<std::uint8_t>() { return H5T_NATIVE_UINT8; }
template <> hid_t native_type<std::uint32_t>() { return H5T_NATIVE_UINT32; }
template <> hid_t native_type<std::uint64_t>() { return H5T_NATIVE_UINT64; }
} // namespace

template <class T>
void H5Object::array(const std::string& name, const std::vector<T>& v) const {
    const hsize_t n = v.size();
    const hid_t s = H5Screate_simple(1, &n, nullptr);
    const hid_t d = check(H5Dcreate2(id_, name.c_str(), native_type<T>(), s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                          "dataset " + name);
    const herr_t e = n ? H5Dwrite(d, native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) : 0;
    H5Sclose(s);
    H5Dclose(d);
    check(e, "write " + name);
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

void H5Object::attr_u64(const std::string& name, std::uint64_t v) const {
    const hid_t s = H5Screate(H5S_SCALAR);
    write_attr(id_, name, H5T_NATIVE_UINT64, s, &v);
    H5Sclose(s);
}

long H5Object::read_long_attr(const std::string& name) const {
    H5Object a(check(H5Aopen(id_, name.c_str(), H5P_DEFAULT), "open attr " + name), &H5Aclose);
    long v = 0;
    check(H5Aread(a.id(), H5T_NATIVE_LONG, &v), "read attr " + name);
    return v;
}

std::uint64_t H5Object::read_u64_attr(const std::string& name) const {
    H5Object a(check(H5Aopen(id_, name.c_str(), H5P_DEFAULT), "open attr " + name), &H5Aclose);
    std::uint64_t v = 0;
    check(H5Aread(a.id(), H5T_NATIVE_UINT64, &v), "read attr " + name);
    return v;
}

bool H5Object::has(const std::string& name) const { return H5Lexists(id_, name.c_str(), H5P_DEFAULT) > 0; }

std::vector<std::string> H5Object::children() const {
    H5G_info_t info;
    check(H5Gget_info(id_, &info), "group info");
    std::vector<std::string> names;
    for (hsize_t i = 0; i < info.nlinks; ++i) {
        const ssize_t n = H5Lget_name_by_idx(id_, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
        check(herr_t(n < 0 ? -1 : 0), "link name");
        std::string name(std::size_t(n) + 1, '\0');
        H5Lget_name_by_idx(id_, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT);
        name.resize(std::size_t(n));
        names.push_back(name);
    }
    return names;
}

std::vector<std::string> H5Object::attribute_names() const {
    H5O_info_t info;
    check(H5Oget_info2(id_, &info, H5O_INFO_NUM_ATTRS), "object info");
    std::vector<std::string> names;
    for (hsize_t i = 0; i < info.num_attrs; ++i) {
        const ssize_t n = H5Aget_name_by_idx(id_, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
        check(herr_t(n < 0 ? -1 : 0), "attribute name");
        std::string name(std::size_t(n) + 1, '\0');
        H5Aget_name_by_idx(id_, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT);
        name.resize(std::size_t(n));
        names.push_back(name);
    }
    return names;
}

std::size_t H5Object::dataset_size(const std::string& name) const {
    H5Object d(check(H5Dopen2(id_, name.c_str(), H5P_DEFAULT), "open " + name), &H5Dclose);
    H5Object sp(H5Dget_space(d.id()), &H5Sclose);
    return std::size_t(H5Sget_simple_extent_npoints(sp.id()));
}

void H5Object::copy_to(const std::string& name, const H5Object& dst) const {
    check(H5Ocopy(id_, name.c_str(), dst.id(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), "copy " + name);
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

void H5Object::require_schema(const std::string& schema, long version) const {
    std::string found;
    try {
        found = read_string_attr("schema");
    } catch (const std::exception&) {
    }
    if (found != schema) throw std::runtime_error("not a " + schema + " group (schema attribute: '" + found + "')");
    if (read_long_attr("schema_version") != version)
        throw std::runtime_error(schema + ": unsupported schema_version (this build reads " + std::to_string(version) + ")");
}

std::vector<double> H5Object::read_dataset(const std::string& name) const {
    H5Object d(check(H5Dopen2(id_, name.c_str(), H5P_DEFAULT), "open " + name), &H5Dclose);
    H5Object s(H5Dget_space(d.id()), &H5Sclose);
    const hssize_t n = H5Sget_simple_extent_npoints(s.id());
    std::vector<double> v(static_cast<std::size_t>(n));
    if (n) check(H5Dread(d.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), "read " + name);
    return v;
}

std::vector<unsigned char> H5Object::read_bytes(const std::string& name) const {
    H5Object d(check(H5Dopen2(id_, name.c_str(), H5P_DEFAULT), "open " + name), &H5Dclose);
    H5Object s(H5Dget_space(d.id()), &H5Sclose);
    const hssize_t n = H5Sget_simple_extent_npoints(s.id());
    std::vector<unsigned char> v(static_cast<std::size_t>(n));
    if (n) check(H5Dread(d.id(), H5T_NATIVE_UCHAR, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), "read " + name);
    return v;
}

std::string H5Object::read_string_attr(const std::string& name) const {
    H5Object a(check(H5Aopen(id_, name.c_str(), H5P_DEFAULT), "open attr " + name), &H5Aclose);
    H5Object t(H5Aget_type(a.id()), &H5Tclose);
    std::string s(H5Tget_size(t.id()), '\0');
    check(H5Aread(a.id(), t.id(), s.data()), "read attr " + name);
    while (!s.empty() && s.back() == '\0') s.pop_back();
    return s;
}

double H5Object::read_double_attr(const std::string& name) const {
    H5Object a(check(H5Aopen(id_, name.c_str(), H5P_DEFAULT), "open attr " + name), &H5Aclose);
    double v = 0;
    check(H5Aread(a.id(), H5T_NATIVE_DOUBLE, &v), "read attr " + name);
    return v;
}

} // namespace granrepro

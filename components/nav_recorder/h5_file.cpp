#include "h5_file.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace gdnav::nav_recorder {

namespace {

// The innermost message of the HDF5 error stack (for exceptions); also silences HDF5's own printing.
std::string h5_error() {
    std::string msg;
    H5Ewalk2(
        H5E_DEFAULT, H5E_WALK_UPWARD,
        [](unsigned, const H5E_error2_t* e, void* data) -> herr_t {
            auto* m = static_cast<std::string*>(data);
            if (m->empty() && e->desc) *m = e->desc;
            return 0;
        },
        &msg);
    H5Eclear2(H5E_DEFAULT);
    return msg.empty() ? "unknown HDF5 error" : msg;
}

template <class T>
T check(T r, const std::string& what) {
    if (r < 0) throw std::runtime_error("HDF5: " + what + ": " + h5_error());
    return r;
}

}  // namespace

H5File::H5File(const std::filesystem::path& path) : path_(path.string()) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    file_ = check(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), "cannot create " + path_);
}

H5File::~H5File() {
    try {
        close();
    } catch (const std::exception&) {
    }
}

int H5File::add_table(const std::string& name, const std::vector<std::string>& columns, std::size_t chunk_rows,
                      int deflate_level) {
    Table t;
    t.columns = columns.size();
    const std::size_t row_bytes = columns.size() * sizeof(double);
    t.mem_type = check(H5Tcreate(H5T_COMPOUND, row_bytes), "compound type");
    hid_t file_type = check(H5Tcreate(H5T_COMPOUND, row_bytes), "compound type");
    for (std::size_t i = 0; i < columns.size(); ++i) {
        check(H5Tinsert(t.mem_type, columns[i].c_str(), i * sizeof(double), H5T_NATIVE_DOUBLE), "column " + columns[i]);
        check(H5Tinsert(file_type, columns[i].c_str(), i * sizeof(double), H5T_IEEE_F64LE), "column " + columns[i]);
    }
    const hsize_t dims[1] = {0};
    const hsize_t max_dims[1] = {H5S_UNLIMITED};
    const hid_t space = check(H5Screate_simple(1, dims, max_dims), "dataspace");
    const hid_t dcpl = check(H5Pcreate(H5P_DATASET_CREATE), "dataset properties");
    const hsize_t chunk[1] = {static_cast<hsize_t>(chunk_rows)};
    check(H5Pset_chunk(dcpl, 1, chunk), "chunk");
    if (deflate_level > 0 && H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0) {
        check(H5Pset_shuffle(dcpl), "shuffle");
        check(H5Pset_deflate(dcpl, static_cast<unsigned>(deflate_level)), "deflate");
    }
    t.dataset = check(H5Dcreate2(file_, name.c_str(), file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
                      "create dataset " + name);
    H5Pclose(dcpl);
    H5Sclose(space);
    H5Tclose(file_type);
    tables_.push_back(t);
    return static_cast<int>(tables_.size() - 1);
}

void H5File::append(int table, const double* data, std::size_t rows) {
    if (rows == 0) return;
    Table& t = tables_.at(static_cast<std::size_t>(table));
    const hsize_t start[1] = {t.rows};
    const hsize_t count[1] = {rows};
    const hsize_t new_size[1] = {t.rows + rows};
    check(H5Dset_extent(t.dataset, new_size), "extend table");
    const hid_t file_space = check(H5Dget_space(t.dataset), "table space");
    check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr), "select rows");
    const hid_t mem_space = check(H5Screate_simple(1, count, nullptr), "memory space");
    const herr_t w = H5Dwrite(t.dataset, t.mem_type, mem_space, file_space, H5P_DEFAULT, data);
    H5Sclose(mem_space);
    H5Sclose(file_space);
    check(w, "write rows");
    t.rows += rows;
}

void H5File::attribute(hid_t loc, const std::string& name, hid_t type, const void* value) {
    if (check(H5Aexists(loc, name.c_str()), "attribute " + name) > 0) check(H5Adelete(loc, name.c_str()), "attribute " + name);
    const hid_t space = check(H5Screate(H5S_SCALAR), "scalar space");
    const hid_t a = check(H5Acreate2(loc, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), "attribute " + name);
    const herr_t w = H5Awrite(a, type, value);
    H5Aclose(a);
    H5Sclose(space);
    check(w, "write attribute " + name);
}

void H5File::set_attribute(const std::string& name, double value) { attribute(file_, name, H5T_NATIVE_DOUBLE, &value); }

void H5File::set_attribute(const std::string& name, std::int64_t value) {
    attribute(file_, name, H5T_NATIVE_INT64, &value);
}

void H5File::set_attribute(const std::string& name, const std::string& value) {
    const hid_t type = check(H5Tcopy(H5T_C_S1), "string type");
    H5Tset_size(type, std::max<std::size_t>(value.size(), 1));
    H5Tset_strpad(type, H5T_STR_NULLPAD);
    attribute(file_, name, type, value.c_str());
    H5Tclose(type);
}

void H5File::set_table_attribute(int table, const std::string& name, const std::string& value) {
    const hid_t type = check(H5Tcopy(H5T_C_S1), "string type");
    H5Tset_size(type, std::max<std::size_t>(value.size(), 1));
    H5Tset_strpad(type, H5T_STR_NULLPAD);
    attribute(tables_.at(static_cast<std::size_t>(table)).dataset, name, type, value.c_str());
    H5Tclose(type);
}

void H5File::write_metrics(const std::string& name, const std::vector<MetricsRow>& rows) {
    constexpr std::size_t kName = 16;
    struct Row {
        char name[kName];
        std::uint64_t n;
        double mean, std, max, final;
    };
    std::vector<Row> data(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        std::memset(data[i].name, 0, kName);
        std::strncpy(data[i].name, rows[i].name.c_str(), kName - 1);
        data[i].n = rows[i].n;
        data[i].mean = rows[i].mean;
        data[i].std = rows[i].std;
        data[i].max = rows[i].max;
        data[i].final = rows[i].final;
    }
    const hid_t str = check(H5Tcopy(H5T_C_S1), "string type");
    H5Tset_size(str, kName);
    H5Tset_strpad(str, H5T_STR_NULLTERM);
    const hid_t type = check(H5Tcreate(H5T_COMPOUND, sizeof(Row)), "metrics type");
    H5Tinsert(type, "name", HOFFSET(Row, name), str);
    H5Tinsert(type, "n", HOFFSET(Row, n), H5T_NATIVE_UINT64);
    H5Tinsert(type, "mean", HOFFSET(Row, mean), H5T_NATIVE_DOUBLE);
    H5Tinsert(type, "std", HOFFSET(Row, std), H5T_NATIVE_DOUBLE);
    H5Tinsert(type, "max", HOFFSET(Row, max), H5T_NATIVE_DOUBLE);
    H5Tinsert(type, "final", HOFFSET(Row, final), H5T_NATIVE_DOUBLE);
    const hsize_t dims[1] = {rows.size()};
    const hid_t space = check(H5Screate_simple(1, dims, nullptr), "metrics space");
    const hid_t ds = check(H5Dcreate2(file_, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                           "create dataset " + name);
    const herr_t w = H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
    H5Dclose(ds);
    H5Sclose(space);
    H5Tclose(type);
    H5Tclose(str);
    check(w, "write " + name);
}

void H5File::flush() { check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush " + path_); }

void H5File::close() {
    if (file_ < 0) return;
    for (auto& t : tables_) {
        H5Tclose(t.mem_type);
        H5Dclose(t.dataset);
    }
    tables_.clear();
    const hid_t f = file_;
    file_ = -1;
    check(H5Fclose(f), "close " + path_);
}

}  // namespace gdnav::nav_recorder

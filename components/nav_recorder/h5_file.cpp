#include "h5_file.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "files/write_error.hpp"

namespace gdnav::nav_recorder {

namespace {

// The file the current entry point works on, for the errors of check().
thread_local const std::string* g_file = nullptr;

// Every public entry point starts with an Entry. HDF5 keeps its error stack and its automatic printing per thread,
// and a component's calls may come from any thread of the host: each entry silences the printing on its own thread
// (the errors become one exception each, never HDF5's diagnostic stack on stderr).
class Entry {
public:
    explicit Entry(const std::string& file) : previous_(g_file) {
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
        g_file = &file;
    }
    ~Entry() { g_file = previous_; }
    Entry(const Entry&) = delete;
    Entry& operator=(const Entry&) = delete;

private:
    const std::string* previous_;
};

struct H5Failure {
    std::string message;  // the innermost message of the error stack
    int errnum{0};        // the operating system's errno when the failure was a refused read or write (else 0)
};

// Reads and clears the error stack. HDF5's POSIX driver puts the OS error into its message ("..., errno = 28, error
// message = 'No space left on device', ...").
H5Failure h5_error() {
    H5Failure f;
    H5Ewalk2(
        H5E_DEFAULT, H5E_WALK_UPWARD,
        [](unsigned, const H5E_error2_t* e, void* data) -> herr_t {
            auto* out = static_cast<H5Failure*>(data);
            if (!e->desc) return 0;
            if (out->message.empty()) out->message = e->desc;
            const char* at = std::strstr(e->desc, "errno = ");
            if (out->errnum == 0 && at) out->errnum = std::atoi(at + 8);
            return 0;
        },
        &f);
    H5Eclear2(H5E_DEFAULT);
    if (f.message.empty()) f.message = "unknown HDF5 error";
    return f;
}

template <class T>
T check(T r, const std::string& what) {
    if (r >= 0) return r;
    const H5Failure f = h5_error();
    if (f.errnum > 0 && g_file) files::throw_write_error(*g_file, f.errnum);
    throw std::runtime_error("HDF5: " + what + ": " + f.message);
}

}  // namespace

H5File::H5File(const std::filesystem::path& path) : path_(path.string()) {
    // HDF5 closes the files still open at the process's exit; one whose last write was refused (a full disk) cannot
    // be closed and that close crashes the library (HDF5 1.10.8: H5F__close_cb). Every file is closed here
    // explicitly, so the library's exit handler is not wanted; it must be declined before the library starts.
    static const bool no_exit_handler = [] {
        H5dont_atexit();
        return true;
    }();
    (void)no_exit_handler;
    const Entry entry(path_);
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
    const Entry entry(path_);
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
    // No creation/modification times in the object headers: a run's file is the same bytes whenever it is written
    // (a rerun of a batch run is compared byte for byte: docs/montecarlo.md, "Damaged runs and a full disk").
    check(H5Pset_obj_track_times(dcpl, false), "track times");
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
    const Entry entry(path_);
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
    const Entry entry(path_);
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
    const Entry entry(path_);
    const hid_t type = check(H5Tcopy(H5T_C_S1), "string type");
    H5Tset_size(type, std::max<std::size_t>(value.size(), 1));
    H5Tset_strpad(type, H5T_STR_NULLPAD);
    attribute(file_, name, type, value.c_str());
    H5Tclose(type);
}

void H5File::set_table_attribute(int table, const std::string& name, const std::string& value) {
    const Entry entry(path_);
    const hid_t type = check(H5Tcopy(H5T_C_S1), "string type");
    H5Tset_size(type, std::max<std::size_t>(value.size(), 1));
    H5Tset_strpad(type, H5T_STR_NULLPAD);
    attribute(tables_.at(static_cast<std::size_t>(table)).dataset, name, type, value.c_str());
    H5Tclose(type);
}

void H5File::write_metrics(const std::string& name, const std::vector<MetricsRow>& rows) {
    const Entry entry(path_);
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
    const hid_t dcpl = check(H5Pcreate(H5P_DATASET_CREATE), "dataset properties");
    check(H5Pset_obj_track_times(dcpl, false), "track times");  // as add_table
    const hid_t ds = check(H5Dcreate2(file_, name.c_str(), type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
                           "create dataset " + name);
    H5Pclose(dcpl);
    const herr_t w = H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
    H5Dclose(ds);
    H5Sclose(space);
    H5Tclose(type);
    H5Tclose(str);
    check(w, "write " + name);
}

void H5File::flush() {
    const Entry entry(path_);
    check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush " + path_);
}

void H5File::close() {
    if (file_ < 0) return;
    const Entry entry(path_);
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

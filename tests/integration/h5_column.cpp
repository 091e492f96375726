#include "h5_column.hpp"

#include <hdf5.h>

namespace gdnav::testing {

std::vector<double> h5_column(const std::filesystem::path& h5, const char* table, const char* name) {
    std::vector<double> v;
    const hid_t f = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0) return v;
    const hid_t d = H5Dopen2(f, table, H5P_DEFAULT);
    if (d >= 0) {
        const hid_t s = H5Dget_space(d);
        hsize_t n = 0;
        H5Sget_simple_extent_dims(s, &n, nullptr);
        const hid_t one = H5Tcreate(H5T_COMPOUND, sizeof(double));
        H5Tinsert(one, name, 0, H5T_NATIVE_DOUBLE);
        v.resize(n);
        if (n == 0 || H5Dread(d, one, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0) v.clear();
        H5Tclose(one);
        H5Sclose(s);
        H5Dclose(d);
    }
    H5Fclose(f);
    return v;
}

}  // namespace gdnav::testing

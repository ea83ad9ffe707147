// SPDX-License-Identifier: GPL-3.0-or-later
// Writes mat73_unwritten_dataset.mat: a MATLAB v7.3 (HDF5) file holding the 300-sample column
// vectors u (a step: 0, then 1) and y (0.001 k) written by libmatio, plus "big", a chunked
// 400000000 x 1 double dataset added with libhdf5 whose chunks are never written: the file stays
// a few KB while the variable claims 3.2 GB. Build and run from tests/data/:
//   gcc gen_mat73_unwritten_dataset.c -I/usr/include/hdf5/serial -lmatio -lhdf5_serial -o
//   /tmp/gen73 /tmp/gen73 mat73_unwritten_dataset.mat
#include <hdf5.h>
#include <matio.h>

#include <stdio.h>
#include <string.h>

static int writeVector(mat_t* m, const char* name, double* data, size_t n) {
    size_t dims[2] = {n, 1};
    matvar_t* v = Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, data, 0);
    const int err = !v || Mat_VarWrite(m, v, MAT_COMPRESSION_NONE) != 0;
    Mat_VarFree(v);
    return err;
}

int main(int argc, char** argv) {
    if (argc != 2)
        return 2;
    double u[300], y[300];
    for (int k = 0; k < 300; ++k) {
        u[k] = k == 0 ? 0.0 : 1.0;
        y[k] = 0.001 * k;
    }
    mat_t* m = Mat_CreateVer(argv[1], NULL, MAT_FT_MAT73);
    if (!m || writeVector(m, "u", u, 300) || writeVector(m, "y", y, 300))
        return 1;
    Mat_Close(m);

    // MATLAB stores an n x 1 array as an HDF5 dataspace of (1, n) (column-major order).
    const hid_t file = H5Fopen(argv[1], H5F_ACC_RDWR, H5P_DEFAULT);
    const hsize_t dims[2] = {1, 400000000}, chunk[2] = {1, 1000000};
    const hid_t space = H5Screate_simple(2, dims, NULL);
    const hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(plist, 2, chunk);
    const hid_t set =
        H5Dcreate2(file, "big", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, plist, H5P_DEFAULT);
    const hid_t strType = H5Tcopy(H5T_C_S1);
    H5Tset_size(strType, strlen("double"));
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const hid_t attr = H5Acreate2(set, "MATLAB_class", strType, scalar, H5P_DEFAULT, H5P_DEFAULT);
    const herr_t err = H5Awrite(attr, strType, "double");
    H5Aclose(attr);
    H5Sclose(scalar);
    H5Tclose(strType);
    H5Dclose(set);
    H5Pclose(plist);
    H5Sclose(space);
    H5Fclose(file);
    return err < 0 || set < 0 ? 1 : 0;
}

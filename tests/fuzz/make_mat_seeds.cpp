// Writes the MAT seeds of the fuzz_mat target: the EMPS variables (the vectors cut to their first
// N samples, the scalars as they are) saved by matio as MAT v5, v5 compressed and v7.3 (when matio
// has HDF5), so the seeds are small but shaped like the real files.
// Usage: fuzz_make_mat_seeds EMPS.mat OUTDIR [N=16]

#include <matio.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

struct Var {
  std::string name;
  std::vector<double> values;
  bool scalar;
};

bool write(const std::string& path, const std::vector<Var>& vars, mat_ft version, matio_compression compression) {
  mat_t* mat = Mat_CreateVer(path.c_str(), nullptr, version);
  if (mat == nullptr) return false;
  bool ok = true;
  for (const Var& v : vars) {
    size_t dims[2] = {v.values.size(), 1};
    matvar_t* mv = Mat_VarCreate(v.name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims,
                                 const_cast<double*>(v.values.data()), MAT_F_DONT_COPY_DATA);
    ok = ok && mv != nullptr && Mat_VarWrite(mat, mv, compression) == 0;
    Mat_VarFree(mv);
  }
  Mat_Close(mat);
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s EMPS.mat OUTDIR [N]\n", argv[0]);
    return 2;
  }
  const std::size_t n = argc > 3 ? std::strtoul(argv[3], nullptr, 10) : 16;
  mat_t* in = Mat_Open(argv[1], MAT_ACC_RDONLY);
  if (in == nullptr) {
    std::fprintf(stderr, "%s: cannot open\n", argv[1]);
    return 1;
  }
  std::vector<Var> vars;
  while (matvar_t* v = Mat_VarReadNext(in)) {
    if (v->class_type == MAT_C_DOUBLE && !v->isComplex && v->rank == 2 && v->data != nullptr) {
      const std::size_t len = v->dims[0] * v->dims[1];
      const double* p = static_cast<const double*>(v->data);
      Var out{v->name, {}, len == 1};
      out.values.assign(p, p + (len == 1 ? 1 : std::min(n, len)));
      vars.push_back(std::move(out));
    }
    Mat_VarFree(v);
  }
  Mat_Close(in);
  const std::string dir = argv[2];
  bool ok = write(dir + "/emps_slice_v5.mat", vars, MAT_FT_MAT5, MAT_COMPRESSION_NONE);
  ok = write(dir + "/emps_slice_v5_zlib.mat", vars, MAT_FT_MAT5, MAT_COMPRESSION_ZLIB) && ok;
  if (!write(dir + "/emps_slice_v73.mat", vars, MAT_FT_MAT73, MAT_COMPRESSION_NONE))
    std::fprintf(stderr, "matio cannot write MAT v7.3 here (no HDF5): skipped\n");
  return ok ? 0 : 1;
}

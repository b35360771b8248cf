#include "theory/global/cholmod_factor.hpp"

#include "theory/global/ldl_substitution.hpp"

#include <dlfcn.h>

#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace affinterp::global {
namespace {

template <class Scalar>
constexpr int xtype = std::is_same_v<Scalar, double> ? CHOLMOD_REAL : CHOLMOD_COMPLEX;

/// `name` in a library CHOLMOD loaded: found in the process's global scope, or in `library` by its name when
/// CHOLMOD was loaded with RTLD_LOCAL (the Python module's). Null when it is not there (another library in
/// its place).
void* loaded_symbol(const char* library, const char* name) {
  if (void* symbol = dlsym(RTLD_DEFAULT, name)) return symbol;
  void* handle = dlopen(library, RTLD_NOW | RTLD_NOLOAD);
  if (!handle) return nullptr;
  void* symbol = dlsym(handle, name);
  dlclose(handle);  // CHOLMOD's own reference keeps it loaded
  return symbol;
}

/// CHOLMOD's BLAS on one thread, once per process, when it is OpenBLAS: the engine runs frames in parallel
/// itself, and OpenBLAS's pool of threads, shared by concurrent callers and spinning between calls, makes a
/// batch of E^R frames at 1M triangles several times slower on 2 cores (bench_scale batch_frames/R with
/// OPENBLAS_NUM_THREADS=2 against 1 measures it). One thread also makes the factor the same whatever the machine's
/// thread count. This sets the thread count of the process's OpenBLAS (numpy's too, in the Python module).
void single_threaded_blas() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (void* set = loaded_symbol("libopenblas.so.0", "openblas_set_num_threads"))
      reinterpret_cast<void (*)(int)>(set)(1);
  });
}

/// No OpenMP team inside CHOLMOD's numeric calls while it lives, for the same reason: Debian's CHOLMOD clears
/// its workspace in OpenMP loops of a fixed 4 threads (CHOLMOD_OMP_NUM_THREADS, compiled in, above
/// OMP_NUM_THREADS), a team woken for each large supernode; on 2 cores those 4 threads take turns, and a
/// factorisation at 1M triangles takes markedly longer in wall clock (bench_scale backend_factor/F with
/// OMP_THREAD_LIMIT=1 against unset measures it). It sets the calling thread's limit of active parallel levels to 0
/// (libgomp keeps one per thread), so that every team is the calling thread alone, and restores it after.
class WithoutOpenMpTeams {
 public:
  WithoutOpenMpTeams() {
    if (!levels().get) return;
    saved_ = levels().get();
    levels().set(0);
  }
  ~WithoutOpenMpTeams() {
    if (levels().get) levels().set(saved_);
  }
  WithoutOpenMpTeams(const WithoutOpenMpTeams&) = delete;
  WithoutOpenMpTeams& operator=(const WithoutOpenMpTeams&) = delete;

 private:
  struct Levels {
    int (*get)() = nullptr;
    void (*set)(int) = nullptr;
  };
  /// libgomp's omp_get_max_active_levels and omp_set_max_active_levels, when CHOLMOD loaded it.
  static const Levels& levels() {
    static const Levels found = [] {
      Levels l;
      void* get = loaded_symbol("libgomp.so.1", "omp_get_max_active_levels");
      void* set = loaded_symbol("libgomp.so.1", "omp_set_max_active_levels");
      if (get && set) l.get = reinterpret_cast<int (*)()>(get), l.set = reinterpret_cast<void (*)(int)>(set);
      return l;
    }();
    return found;
  }
  int saved_ = 0;
};

void start(cholmod_common& common) {
  single_threaded_blas();
  cholmod_start(&common);
  common.supernodal = CHOLMOD_SUPERNODAL;
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_AMD;
  common.print = 0;
}

/// K's lower triangle as CHOLMOD's symmetric matrix, sharing its arrays (K compressed).
template <class Scalar>
cholmod_sparse view(const Eigen::SparseMatrix<Scalar>& K) {
  if (!K.isCompressed()) throw std::invalid_argument("CholmodFactor: the matrix must be compressed");
  cholmod_sparse A{};
  A.nrow = A.ncol = static_cast<std::size_t>(K.rows());
  A.nzmax = static_cast<std::size_t>(K.nonZeros());
  A.p = const_cast<int*>(K.outerIndexPtr());
  A.i = const_cast<int*>(K.innerIndexPtr());
  A.x = const_cast<Scalar*>(K.valuePtr());
  A.stype = -1;  // the lower triangle
  A.itype = CHOLMOD_INT;
  A.xtype = xtype<Scalar>;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  return A;
}

}  // namespace

template <class Scalar>
CholmodFactor<Scalar>::CholmodFactor() {
  start(common_);
}

template <class Scalar>
CholmodFactor<Scalar>::~CholmodFactor() {
  if (L_) cholmod_free_factor(&L_, &common_);
  cholmod_finish(&common_);
}

template <class Scalar>
void CholmodFactor<Scalar>::analyse(const SparseMatrix& K) {
  if (L_) cholmod_free_factor(&L_, &common_);
  cholmod_sparse A = view(K);
  L_ = cholmod_analyze(&A, &common_);
  if (!L_) throw std::runtime_error("CHOLMOD's analysis failed (status " + std::to_string(common_.status) + ")");
}

template <class Scalar>
bool CholmodFactor<Scalar>::factorise(const SparseMatrix& K, std::size_t /*threads*/) {
  if (!L_) analyse(K);  // a real factor was turned into columns of our own below: supernodes again for this one
  cholmod_sparse A = view(K);
  const WithoutOpenMpTeams serial;
  const int ok = cholmod_factorize(&A, L_, &common_);
  if (!ok || common_.status != CHOLMOD_OK || L_->minor != L_->n) return false;
  // (min / max of diag L)² is the ratio of the smallest to the largest pivot of the LDLᴴ form
  const double ratio = cholmod_rcond(L_, &common_);
  if (!(std::isfinite(ratio) && ratio > 1e-12)) return false;
  if constexpr (std::is_same_v<Scalar, double>) {
    // E^F's real L is factored once and solved every frame: as simplicial L D Lᵀ columns without the zeros of
    // the supernodes' amalgamation, its two right-hand sides take one pass of ldl_substitution.hpp, faster
    // than with those zeros and than CHOLMOD's supernodal solve, whose BLAS calls pack tiny blocks (bench_scale
    // backend_solve/F measures the three)
    if (!cholmod_change_factor(CHOLMOD_REAL, false, false, true, true, L_, &common_))
      throw std::runtime_error("CHOLMOD's change of factor failed (status " + std::to_string(common_.status) + ")");
    const auto n = static_cast<Eigen::Index>(L_->n);
    const int* p = static_cast<const int*>(L_->p);
    const int* i = static_cast<const int*>(L_->i);
    const auto* x = static_cast<const double*>(L_->x);
    columns_ = Columns{{0},
                       {},
                       {},
                       Eigen::VectorXd(n),
                       std::vector<int>(static_cast<const int*>(L_->Perm), static_cast<const int*>(L_->Perm) + n),
                       split_subtrees(n, p, i, 1)};  // from the structure, the amalgamation's zeros included
    columns_.row.reserve(static_cast<std::size_t>(p[n])), columns_.value.reserve(static_cast<std::size_t>(p[n]));
    for (Eigen::Index j = 0; j < n; ++j) {
      columns_.D[j] = x[p[j]];  // each column's diagonal first
      for (int s = p[j] + 1; s < p[j + 1]; ++s)
        if (x[s] != 0) columns_.row.push_back(i[s]), columns_.value.push_back(x[s]);
      columns_.start.push_back(static_cast<int>(columns_.row.size()));
    }
    cholmod_free_factor(&L_, &common_);
  }
  return true;
}

template <class Scalar>
void CholmodFactor<Scalar>::solve_in_place(Block& X, std::size_t threads) const {
  if constexpr (std::is_same_v<Scalar, double>) {
    if (!L_) {  // P x = L D Lᵀ Pᵀ x, perm[k] the unknown of pivot k
      ldl_solve_permuted(
          LdlColumns<double>{columns_.D.size(), columns_.start.data(), columns_.row.data(), columns_.value.data(), 0,
                             columns_.D.data(), columns_.subtrees ? &*columns_.subtrees : nullptr},
          columns_.perm.data(), X, threads);
      return;
    }
  }
  cholmod_common common;
  start(common);
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> B = X;  // CHOLMOD's dense is column-major
  cholmod_dense b{};
  b.nrow = static_cast<std::size_t>(B.rows()), b.ncol = static_cast<std::size_t>(B.cols());
  b.nzmax = b.nrow * b.ncol, b.d = b.nrow;
  b.x = B.data();
  b.xtype = xtype<Scalar>, b.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = [&] {
    const WithoutOpenMpTeams serial;
    return cholmod_solve(CHOLMOD_A, L_, &b, &common);
  }();
  if (!x) {
    cholmod_finish(&common);
    throw std::runtime_error("CHOLMOD's solve failed (status " + std::to_string(common.status) + ")");
  }
  X = Eigen::Map<const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>>(static_cast<const Scalar*>(x->x),
                                                                              B.rows(), B.cols());
  cholmod_free_dense(&x, &common);
  cholmod_finish(&common);
}

template <class Scalar>
std::unique_ptr<SparseFactor<Scalar>> CholmodFactor<Scalar>::clone() const {
  auto copy = std::make_unique<CholmodFactor>();
  if (L_) copy->L_ = cholmod_copy_factor(L_, &copy->common_);
  copy->columns_ = columns_;
  return copy;
}

template <class Scalar>
double CholmodFactor<Scalar>::factor_bytes() const {
  if (!L_) return static_cast<double>(columns_.value.size() * sizeof(double) + columns_.row.size() * sizeof(int));
  const double values = static_cast<double>(L_->is_super ? L_->xsize : L_->nzmax);
  const double indices = static_cast<double>(L_->is_super ? L_->ssize : L_->nzmax);
  return values * static_cast<double>(sizeof(Scalar)) + indices * static_cast<double>(sizeof(int));
}

template class CholmodFactor<double>;
template class CholmodFactor<std::complex<double>>;

}  // namespace affinterp::global

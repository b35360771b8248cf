#include "theory/global/hermitian_form.hpp"

#include <vector>

namespace affinterp::global {

Eigen::SparseMatrix<double> realified(const Eigen::SparseMatrix<std::complex<double>>& H) {
  using Iterator = Eigen::SparseMatrix<std::complex<double>>::InnerIterator;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(4 * H.nonZeros()));
  for (Eigen::Index l = 0; l < H.outerSize(); ++l)
    for (Iterator it(H, l); it; ++it) {
      const Eigen::Index k = it.row();
      const double re = it.value().real(), im = it.value().imag();
      entries.emplace_back(2 * k, 2 * l, re), entries.emplace_back(2 * k + 1, 2 * l + 1, re);
      entries.emplace_back(2 * k + 1, 2 * l, im), entries.emplace_back(2 * k, 2 * l + 1, -im);
    }
  Eigen::SparseMatrix<double> G(2 * H.rows(), 2 * H.cols());
  G.setFromTriplets(entries.begin(), entries.end());
  return G;
}

}  // namespace affinterp::global

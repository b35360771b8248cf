#include "theory/sym3/algorithms.hpp"

#include "theory/sym3/affinterp.hpp"
#include "theory/sym3/diagonalisation.hpp"
#include "theory/sym3/pade.hpp"
#include "theory/sym3/spectral_decomposition.hpp"
#include "theory/sym3/viete.hpp"

#include <algorithm>
#include <array>

namespace affinterp::sym3 {
namespace {

constexpr std::array eig_catalogue{
    EigAlgorithm{"eigen-qr", eigenvalues_eigen_qr},   EigAlgorithm{"eigen-direct", eigenvalues_eigen_direct},
    EigAlgorithm{"viete", eigenvalues_viete},         EigAlgorithm{"viete-clamped", eigenvalues_viete_clamped},
    EigAlgorithm{"affinterp", eigenvalues_affinterp},
};

constexpr std::array exp_catalogue{
    ExpAlgorithm{"eigen-qr-diag", exp_eigen_qr_diag},
    ExpAlgorithm{"eigen-direct-diag", exp_eigen_direct_diag},
    ExpAlgorithm{"eigen-pade", exp_eigen_pade},
    ExpAlgorithm{"thesis-sd-printed", exp_sd_printed},
    ExpAlgorithm{"thesis-sd-corrected", exp_sd_corrected},
    ExpAlgorithm{"thesis-improved-sd", exp_improved_sd},
    ExpAlgorithm{"thesis-improved-sd-clamped", exp_improved_sd_clamped},
    ExpAlgorithm{"affinterp", exp_affinterp},
};

template <class Algorithm, std::size_t N>
const Algorithm* find(const std::array<Algorithm, N>& catalogue, std::string_view name) {
  const auto it = std::ranges::find(catalogue, name, &Algorithm::name);
  return it == catalogue.end() ? nullptr : &*it;
}

}  // namespace

std::span<const EigAlgorithm> eig_algorithms() { return eig_catalogue; }
std::span<const ExpAlgorithm> exp_algorithms() { return exp_catalogue; }
const EigAlgorithm* find_eig(std::string_view name) { return find(eig_catalogue, name); }
const ExpAlgorithm* find_exp(std::string_view name) { return find(exp_catalogue, name); }

}  // namespace affinterp::sym3

// theta_6: this project's optimized transform of the six power moments (docs/reference.md §8),
// the answer of optimize_transform for (z, ..., z^6) written out, so that a stored format uses it
// without searching. Seed 004 §2.5 gains 30.5 bits with a transform it does not print; this one
// gains 30.587 over the canonical (identity) storage, against the certified bound of 32.94 bits
// from the difference body (tests/moments_quantization_test.cpp re-derives both, and checks that
// q = A b(z) + c stays in [0, 1]^6 on all of [0, 1] with the exact row ranges).
#include "moments/quantization_transform.h"

namespace mb {

QuantizationTransform power6_optimized_transform() {
  QuantizationTransform t{Eigen::MatrixXd(6, 6), Eigen::VectorXd(6)};
  t.A << -3.292775659691495, 70.642557960165547, -239.56698993877598, 286.53062661154928,
      -111.62014280626268, -1.7782319746234658,  //
      33.590732068511798, -365.66514661510359, 1455.7593902832662, -2619.6462125850121,
      2172.7383581196768, -675.77712185948678,  //
      -1.9094215445962657, 37.641582046072159, -240.05654798171102, 554.12151968690307,
      -548.04097626626378, 198.24384375346236,  //
      27.138215131106797, -245.35549356566753, 875.1036913786196, -1534.2248179076585,
      1316.0076961593566, -438.66929196419647,  //
      -18.942978022418099, 135.35727996361786, -460.34775105969788, 786.18359513094754,
      -639.91861385209938, 197.66846860697819,  //
      0.084932490011993378, -126.26082909591179, 813.67894138522638, -1897.1839933060251,
      1885.5496484937885, -676.86868559061259;
  t.c << 0.04197319600385685, 1.3705888917492594e-11, 0.99999924349160163, 7.6844799697890005e-07,
      0.99999923266697199, 0.99998568591546433;
  return t;
}

}  // namespace mb

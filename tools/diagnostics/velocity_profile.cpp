// The radiated velocity around the tyre (issue 11 notes): from a run's contact.h5, the RMS over
// time (after the first `skip` samples) of /surface/velocity at each position around the tyre,
// averaged in power over the lateral positions, printed against the arc position from the bottom
// (negative: behind). Shows where on the circumference a model's radiating velocity lives.
//   velocity_profile contact.h5 [skip] [half_width_m]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/hdf5_reader.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: velocity_profile contact.h5 [skip] [half_width_m]\n");
    return 2;
  }
  const rollnoise::Hdf5Reader h5(argv[1]);
  const std::size_t skip = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 0;
  const double half = argc > 3 ? std::atof(argv[3]) : 0.1;
  const rollnoise::Hdf5Array v = h5.read_numbers("/surface/velocity", 3, std::size_t{1} << 31);
  const std::size_t samples = v.dims[0], ny = v.dims[1], around = v.dims[2];
  const double circumference = *h5.number_attribute("/", "radius_m") * 2.0 * M_PI;
  const double dx = circumference / static_cast<double>(around);
  std::vector<double> ms(around, 0.0);
  for (std::size_t n = skip; n < samples; ++n)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t g = 0; g < around; ++g) {
        const double x = v.values[(n * ny + j) * around + g];
        ms[g] += x * x;
      }
  double total = 0.0;
  for (std::size_t g = 0; g < around; ++g) {
    ms[g] /= static_cast<double>((samples - skip) * ny);
    total += ms[g];
  }
  std::printf("# whole belt: mean-square velocity %.4e (m/s)^2\n# arc_m  rms_m_per_s  share_of_power\n", total / static_cast<double>(around));
  for (std::size_t g = 0; g < around; ++g) {
    const double s = g <= around / 2 ? static_cast<double>(g) * dx : (static_cast<double>(g) - static_cast<double>(around)) * dx;
    if (std::abs(s) <= half) std::printf("%8.4f %.4e %.4e\n", s, std::sqrt(ms[g]), ms[g] / total);
  }
  return 0;
}

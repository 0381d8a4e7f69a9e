#pragma once
// Weights that make every third-octave band of an FRF count the same, however densely it is
// sampled: measured FRFs have evenly spaced lines, so the decade above 1 kHz would otherwise
// hold ten times the points of the decade below and decide the fit alone.
#include <Eigen/Core>

namespace rollnoise {

// The IEC 61260-1 base-10 third-octave band of a frequency: mid-band f_m = 1000·10^(x/10) Hz
// with band edges f_m·10^(±1/20), so x = round(10·log10(f/1000)).
int third_octave_band(double frequency_hz);

// w_k = 1/(number of points in the band of point k), for frequencies > 0: each band's weights
// add up to 1.
Eigen::VectorXd band_weights(const Eigen::VectorXd& frequency_hz);

}  // namespace rollnoise

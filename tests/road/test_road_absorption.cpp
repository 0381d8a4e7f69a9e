// The acoustics of porous roads (road/porous_layer.hpp, layered_absorber.hpp,
// road_absorption.hpp) against the limits the models must reach, derived independently here.
#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "core/config_table.hpp"
#include "core/error.hpp"
#include "road/layered_absorber.hpp"
#include "road/porous_layer.hpp"
#include "road/road_absorption.hpp"
#include "road/road_surface.hpp"
#include "road/road_test_support.hpp"

namespace rollnoise {
namespace {

using Complex = std::complex<double>;

// A porous asphalt layer of the size published for such roads (Ω 0.2, σ 5 kPa·s/m², α∞ 2.5,
// 40 mm): the limits below hold for any such values.
PorousLayer asphalt(PorousModel model = PorousModel::hamet_berengier, double thickness = 0.04) {
  PorousLayer layer;
  layer.model = model;
  layer.porosity = 0.2;
  layer.flow_resistivity = 5000.0;
  layer.tortuosity = 2.5;
  layer.thickness = thickness;
  layer.viscous_length = 150e-6;
  layer.thermal_length = 450e-6;
  return layer;
}

double rho_c(const AirProperties& air) { return air.density * air.sound_speed; }

TEST(RoadAbsorption, AirAt20Degrees) {
  const AirProperties air = air_at();
  EXPECT_NEAR(air.density, 1.204, 0.001);
  EXPECT_NEAR(air.sound_speed, 343.2, 0.1);
  EXPECT_NEAR(air.viscosity, 1.813e-5, 0.002e-5);
}

// At low frequency the pores' air is moved by the flow resistance alone, ρ → σ/(iω), and
// compressed isothermally, K → P₀/Ω: Z_c → √(σP₀/(iωΩ)), k → √(ωσΩ/(iP₀))·… (the flow-resistive
// limit, Hamet & Bérengier 1993). The first corrections are of order f/f_μ and f/f_θ
// (f_μ = σΩ/(2πρ₀α∞) ≈ 53 Hz, f_θ = σΩ/(2πρ₀Pr) ≈ 186 Hz here): at 0.05 Hz, 1e-3.
TEST(RoadAbsorption, HametBerengierLowFrequencyLimitIsFlowResistive) {
  const AirProperties air = air_at();
  const PorousLayer layer = asphalt();
  const double f = 0.05, omega = 2.0 * std::numbers::pi * f;
  const PorousLayerWave wave = porous_layer_wave(layer, air, f);
  const Complex i(0.0, 1.0);
  const Complex zc = std::sqrt(layer.flow_resistivity * air.static_pressure / (i * omega * layer.porosity));
  const Complex k = std::sqrt(omega * layer.flow_resistivity * layer.porosity / (i * air.static_pressure));
  EXPECT_LE(std::abs(wave.characteristic_impedance / zc - 1.0), 2e-3);
  EXPECT_LE(std::abs(wave.wavenumber / (k.imag() > 0.0 ? -k : k) - 1.0), 2e-3);
  // The rigid-backed layer: the isothermal stiffness of its air, −i P₀/(Ωωd), and a resistance
  // σd/3 from the flow plus (γ − 1)ρ₀Pr P₀/(γσΩ²d) from the thermal relaxation (the expansion
  // of −iZ_c cot kd to first order in kd and in f/f_θ).
  LayeredAbsorber absorber({layer}, air);
  const double f_low = 0.5, w_low = 2.0 * std::numbers::pi * f_low;
  const Complex z = absorber.normalised_impedance(f_low) * rho_c(air);
  const double d = layer.thickness, gamma = air.ratio_of_specific_heats;
  const double stiffness = -air.static_pressure / (layer.porosity * w_low * d);
  const double resistance = layer.flow_resistivity * d / 3.0 +
                            (gamma - 1.0) * air.density * air.prandtl * air.static_pressure /
                                (gamma * layer.flow_resistivity * layer.porosity * layer.porosity * d);
  EXPECT_NEAR(z.imag() / stiffness, 1.0, 0.01);
  EXPECT_NEAR(z.real() / resistance, 1.0, 0.01);
}

// The first absorption peak of a rigid-backed layer sits at its quarter-wave resonance; the
// wave in the pores travels at c/√α∞ at high frequency and slower below (the viscous drag adds
// inertia), so the peak is at or slightly below c/(4√α∞ d).
TEST(RoadAbsorption, FirstPeakNearTheQuarterWaveFrequency) {
  const AirProperties air = air_at();
  for (const double thickness : {0.03, 0.04, 0.05}) {
    const LayeredAbsorber absorber({asphalt(PorousModel::hamet_berengier, thickness)}, air);
    const double quarter_wave = air.sound_speed / (4.0 * std::sqrt(2.5) * thickness);
    double best = 0.0, peak = 0.0;
    for (double f = 100.0; f < 1.5 * quarter_wave; f *= 1.001) {
      const double alpha = absorber.absorption_coefficient(f);
      if (alpha > best) {
        best = alpha;
        peak = f;
      }
    }
    EXPECT_LE(peak, quarter_wave) << thickness;
    EXPECT_GE(peak, 0.8 * quarter_wave) << thickness;
    EXPECT_GT(best, 0.5) << thickness;
  }
}

// A passive surface takes energy in: Re Z > 0 and 0 <= α <= 1 at every frequency.
TEST(RoadAbsorption, Passive) {
  const AirProperties air = air_at();
  for (const PorousModel model : {PorousModel::hamet_berengier, PorousModel::jca}) {
    PorousLayer base = asphalt(model, 0.045);
    base.flow_resistivity = 1500.0;
    base.tortuosity = 1.8;
    const LayeredAbsorber one({asphalt(model)}, air);
    const LayeredAbsorber two({asphalt(model, 0.025), base}, air);
    for (double f = 1.0; f < 40000.0; f *= 1.01) {
      for (const LayeredAbsorber* absorber : {&one, &two}) {
        EXPECT_GT(absorber->normalised_impedance(f).real(), 0.0) << f;
        const double alpha = absorber->absorption_coefficient(f);
        EXPECT_GE(alpha, 0.0) << f;
        EXPECT_LE(alpha, 1.0) << f;
      }
    }
  }
}

// One layer of thickness d is two identical layers of d/2 (the transfer matrices compose):
// equal to rounding.
TEST(RoadAbsorption, OneLayerIsTwoHalves) {
  const AirProperties air = air_at();
  for (const PorousModel model : {PorousModel::hamet_berengier, PorousModel::jca}) {
    const LayeredAbsorber whole({asphalt(model, 0.05)}, air);
    const LayeredAbsorber halves({asphalt(model, 0.025), asphalt(model, 0.025)}, air);
    for (double f = 20.0; f < 20000.0; f *= 1.1) {
      const Complex a = whole.normalised_impedance(f), b = halves.normalised_impedance(f);
      EXPECT_LE(std::abs(a - b), 1e-11 * std::abs(a)) << f;
    }
  }
}

// Johnson–Champoux–Allard at high frequency: the rigid frame's tortuous pores, k → ω√α∞/c and
// Z_c → ρ₀c√α∞/Ω, approached as the boundary layers thin, ∝ δ/Λ ∝ f^{−1/2}.
TEST(RoadAbsorption, JcaHighFrequencyLimit) {
  const AirProperties air = air_at();
  const PorousLayer layer = asphalt(PorousModel::jca);
  const auto deviation = [&](double f) {
    const PorousLayerWave wave = porous_layer_wave(layer, air, f);
    const double k_inf = 2.0 * std::numbers::pi * f * std::sqrt(layer.tortuosity) / air.sound_speed;
    const double z_inf = rho_c(air) * std::sqrt(layer.tortuosity) / layer.porosity;
    EXPECT_LE(std::abs(wave.characteristic_impedance / z_inf - 1.0), 0.05) << f;
    return std::abs(wave.wavenumber / k_inf - 1.0);
  };
  const double at_1mhz = deviation(1e6), at_16mhz = deviation(16e6);
  EXPECT_LE(at_1mhz, 0.05);
  EXPECT_NEAR(at_1mhz / at_16mhz, 4.0, 0.4);  // f^{−1/2}
}

// JCA tends to Hamet–Bérengier where their relaxation functions meet: at low frequency, with the
// thermal length of straight cylindrical pores Λ' = √(8η/(σΩ)) (then both thermal frequencies
// are σΩ/(2πρ₀Pr)); the difference falls in proportion to f.
TEST(RoadAbsorption, JcaMeetsHametBerengierAtLowFrequency) {
  const AirProperties air = air_at();
  PorousLayer jca = asphalt(PorousModel::jca);
  jca.thermal_length = std::sqrt(8.0 * air.viscosity / (jca.flow_resistivity * jca.porosity));
  const PorousLayer hb = asphalt(PorousModel::hamet_berengier);
  const auto difference = [&](double f) {
    const PorousLayerWave a = porous_layer_wave(jca, air, f), b = porous_layer_wave(hb, air, f);
    return std::max(std::abs(a.density / b.density - 1.0), std::abs(a.bulk_modulus / b.bulk_modulus - 1.0));
  };
  // (JCA's low-frequency inertia exceeds HB's ρ₀α∞/Ω by the factor 1 + 2α∞η/(σΛ²Ω), a term
  // that the flow resistance outweighs as f → 0.)
  EXPECT_LE(difference(0.01), 1e-3);
  EXPECT_NEAR(difference(0.1) / difference(0.01), 10.0, 1.0);
  // And both reach the same rigid-frame limit at high frequency.
  const PorousLayerWave a = porous_layer_wave(jca, air, 1e7), b = porous_layer_wave(hb, air, 1e7);
  EXPECT_LE(std::abs(a.wavenumber / b.wavenumber - 1.0), 0.02);
}

// [road.absorption]: rigid by default and exactly; one layer's keys in the table or `layers`.
class AbsorptionTable : public ::testing::Test {
 protected:
  RoadAbsorption read(const std::string& text) {
    holder_ = toml::parse(text);
    const ConfigTable road(*holder_["road"].as_table(), "case.toml", "road");
    RoadAbsorption absorption = read_road_absorption(road);
    road.reject_unknown_keys();
    return absorption;
  }
  std::string error_of(const std::string& text) {
    try {
      read(text);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
  toml::table holder_;
};

TEST_F(AbsorptionTable, RigidByDefault) {
  const RoadAbsorption absent = read("[road]\n");
  EXPECT_TRUE(absent.rigid());
  EXPECT_EQ(absent.normalised_admittance(1000.0), Complex(0.0, 0.0));
  EXPECT_TRUE(read("[road]\n[road.absorption]\nmodel = \"rigid\"\n").rigid());
  // And a surface built by the factory carries it.
  holder_ = toml::parse("[road]\ntype = \"flat\"\n[road.absorption]\nmodel = \"hamet_berengier\"\nporosity = 0.2\n"
                        "flow_resistivity = 5000\ntortuosity = 2.5\nthickness = 0.04\n");
  const auto surface = make_road_surface(ConfigTable(*holder_["road"].as_table(), "case.toml", "road"), 0.0, 1.0, 0.0);
  EXPECT_FALSE(surface->absorption().rigid());
  holder_ = toml::parse("[road]\ntype = \"flat\"\n");
  EXPECT_TRUE(make_road_surface(ConfigTable(*holder_["road"].as_table(), "case.toml", "road"), 0.0, 1.0, 0.0)
                  ->absorption()
                  .rigid());
}

TEST_F(AbsorptionTable, OneLayerInTheTableIsALayersListOfOne) {
  const RoadAbsorption direct = read(
      "[road]\n[road.absorption]\nmodel = \"jca\"\nporosity = 0.2\nflow_resistivity = 5000\ntortuosity = 2.5\n"
      "thickness = 0.04\nviscous_length = 150e-6\nthermal_length = 450e-6\n");
  const RoadAbsorption listed = read(
      "[road]\n[road.absorption]\nmodel = \"jca\"\nlayers = [{porosity = 0.2, flow_resistivity = 5000, "
      "tortuosity = 2.5, thickness = 0.04, viscous_length = 150e-6, thermal_length = 450e-6}]\n");
  EXPECT_EQ(direct.normalised_admittance(800.0), listed.normalised_admittance(800.0));
  EXPECT_EQ(direct.normalised_admittance(800.0),
            1.0 / LayeredAbsorber({asphalt(PorousModel::jca)}, air_at()).normalised_impedance(800.0));
}

TEST_F(AbsorptionTable, AirKeys) {
  const RoadAbsorption cold = read(
      "[road]\n[road.absorption]\nmodel = \"hamet_berengier\"\nporosity = 0.2\nflow_resistivity = 5000\n"
      "tortuosity = 2.5\nthickness = 0.04\ntemperature = 0\nstatic_pressure = 90000\n");
  EXPECT_NEAR(cold.air.sound_speed, 331.3, 0.2);
  EXPECT_NEAR(cold.air.density, 90000.0 / (287.05 * 273.15), 1e-9);
}

TEST_F(AbsorptionTable, BadValuesNameTheKeyAndWhatIsAllowed) {
  const std::string layer = "flow_resistivity = 5000\ntortuosity = 2.5\nthickness = 0.04\n";
  const std::string head = "[road]\n[road.absorption]\nmodel = \"hamet_berengier\"\n";
  std::string message = error_of(head + "porosity = 1.2\n" + layer);
  EXPECT_MENTIONS(message, "case.toml");
  EXPECT_MENTIONS(message, "[road.absorption] porosity");
  EXPECT_MENTIONS(message, "between 0 and 1");
  EXPECT_MENTIONS(error_of(head + "porosity = 0.2\nflow_resistivity = 0\ntortuosity = 2.5\nthickness = 0.04\n"),
                  "[road.absorption] flow_resistivity: must be > 0");
  EXPECT_MENTIONS(error_of(head + "porosity = 0.2\nflow_resistivity = 5000\ntortuosity = 0.9\nthickness = 0.04\n"),
                  "[road.absorption] tortuosity: must be >= 1");
  EXPECT_MENTIONS(error_of(head + "porosity = 0.2\nflow_resistivity = 5000\ntortuosity = 2\nthickness = -0.04\n"),
                  "[road.absorption] thickness: must be > 0");
  message = error_of("[road]\n[road.absorption]\nmodel = \"delany_bazley\"\n");
  EXPECT_MENTIONS(message, "[road.absorption] model");
  EXPECT_MENTIONS(message, "\"hamet_berengier\"");
  EXPECT_MENTIONS(error_of(head + "layers = []\n"), "[road.absorption] layers: is empty");
  EXPECT_MENTIONS(error_of(head + "layers = [{porosity = 0.2, flow_resistivity = 5000, tortuosity = 2.5, "
                                  "thickness = 0.02}, {porosity = 0, flow_resistivity = 5000, tortuosity = 2.5, "
                                  "thickness = 0.02}]\n"),
                  "[road.absorption.layers[2]] porosity");
  EXPECT_MENTIONS(error_of(head + "porosity = 0.2\n" + layer + "porosty = 0.2\n"), "porosty: unknown key");
  EXPECT_MENTIONS(error_of("[road]\n[road.absorption]\nmodel = \"jca\"\nporosity = 0.2\n" + layer),
                  "[road.absorption] viscous_length: is required");
}

}  // namespace
}  // namespace rollnoise

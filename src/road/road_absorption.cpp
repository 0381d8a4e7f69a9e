#include "road/road_absorption.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "core/config_table.hpp"
#include "core/csv.hpp"

namespace rollnoise {
namespace {

const std::vector<std::string> porous_models{"hamet_berengier", "jca"};

// One porous layer's keys in `table` (a layer of `layers`, or the absorption table itself).
PorousLayer read_layer(const ConfigTable& table, PorousModel model) {
  PorousLayer layer;
  layer.model = model;
  layer.porosity = table.number("porosity");
  if (!(layer.porosity > 0.0 && layer.porosity < 1.0))
    table.fail("porosity", "must lie strictly between 0 and 1: the connected air-void fraction (got " +
                               format_number(layer.porosity) + ")");
  layer.flow_resistivity = table.number("flow_resistivity");
  if (!(layer.flow_resistivity > 0.0))
    table.fail("flow_resistivity", "must be > 0 Pa·s/m² (got " + format_number(layer.flow_resistivity) + ")");
  layer.tortuosity = table.number("tortuosity");
  if (!(layer.tortuosity >= 1.0))
    table.fail("tortuosity", "must be >= 1: the pores' path length over the straight one, squared (got " +
                                 format_number(layer.tortuosity) + ")");
  layer.thickness = table.number("thickness");
  if (!(layer.thickness > 0.0)) table.fail("thickness", "must be > 0 m (got " + format_number(layer.thickness) + ")");
  if (model == PorousModel::jca) {
    layer.viscous_length = table.number("viscous_length");
    if (!(layer.viscous_length > 0.0))
      table.fail("viscous_length", "must be > 0 m (got " + format_number(layer.viscous_length) + ")");
    layer.thermal_length = table.number("thermal_length");
    if (!(layer.thermal_length > 0.0))
      table.fail("thermal_length", "must be > 0 m (got " + format_number(layer.thermal_length) + ")");
  }
  return layer;
}

PorousModel model_of(const std::string& name) {
  return name == "jca" ? PorousModel::jca : PorousModel::hamet_berengier;
}

}  // namespace

std::complex<double> RoadAbsorption::normalised_admittance(double frequency) const {
  if (!absorber) return {0.0, 0.0};
  return 1.0 / absorber->normalised_impedance(frequency);
}

RoadAbsorption read_road_absorption(const ConfigTable& road) {
  RoadAbsorption out;
  const std::optional<ConfigTable> table = road.subtable("absorption");
  if (!table) return out;
  out.model = table->choice("model", {"rigid", "hamet_berengier", "jca"}, "rigid");
  const double temperature = table->number("temperature", 20.0);
  if (!(temperature > -60.0 && temperature < 80.0))
    table->fail("temperature", "must lie between -60 and 80 °C, the air's temperature (got " + format_number(temperature) + ")");
  const double pressure = table->number("static_pressure", 101325.0);
  if (!(pressure > 50000.0 && pressure < 120000.0))
    table->fail("static_pressure",
                "must lie between 50000 and 120000 Pa, the air's static pressure (got " + format_number(pressure) + ")");
  out.air = air_at(temperature, pressure);
  if (out.model == "rigid") {
    table->reject_unknown_keys();
    return out;
  }
  std::vector<PorousLayer> layers;
  if (const toml::node* list = table->raw("layers")) {
    const toml::array* array = list->as_array();
    if (!array) table->fail("layers", "must be a list of layer tables, top first: layers = [{ porosity = ..., ... }, ...]");
    if (array->empty())
      table->fail("layers", "is empty: give at least one layer table, top first (or the layer's keys in the table itself)");
    for (std::size_t n = 0; n < array->size(); ++n) {
      const toml::table* entry = (*array)[n].as_table();
      const std::string section = table->section() + ".layers[" + std::to_string(n + 1) + "]";
      if (!entry)
        table->fail("layers", "entry " + std::to_string(n + 1) + " must be a table of a layer's keys (porosity, "
                              "flow_resistivity, tortuosity, thickness, ...)");
      const ConfigTable layer(*entry, table->source_of("layers"), section);
      const std::string model = layer.choice("model", porous_models, out.model);
      layers.push_back(read_layer(layer, model_of(model)));
      layer.reject_unknown_keys();
    }
  } else {
    layers.push_back(read_layer(*table, model_of(out.model)));
  }
  table->reject_unknown_keys();
  out.absorber.emplace(std::move(layers), out.air);
  return out;
}

}  // namespace rollnoise

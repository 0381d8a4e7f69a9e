#pragma once
// `rollnoise road ROAD.toml|PROFILE_FILE`: generate or read a road and analyse it as a road
// engineer would (MPD, texture spectrum, ISO 8608 class), so a user sees what the contact
// solver will roll over.
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace rollnoise {

struct RoadOptions {
  std::string input;                  // a TOML with a [road] table, a surface file, or a profile file
  std::string out;                    // default out/<input name>
  std::vector<std::string> overrides; // --set road.key=value
  double length = 7.0;                // m of a generated road to analyse
  double spacing = 0.2e-3;            // m between the samples of a generated road
  bool spacing_given = false;         // --spacing was given (else a texture road is read at its own grid)
  int lines = 1;                      // lateral lines of a generated road
  double width = 0.16;                // m across which the lines are spread
  bool force = false;                 // run even when the size estimate says it does not fit
  bool width_given = false;
  // --contact-law: the law of cells --cell DX,DY of the tread rubber (--tread-modulus, --tread-poisson)
  bool contact_law = false;
  double tread_modulus = 0.0;         // Pa
  double tread_poisson = 0.48;
  std::vector<double> cell;           // DX, DY (m)
  std::vector<double> ground_effect;  // --ground-effect HS,D,HR (m)
};

CLI::App* add_road_command(CLI::App& app, RoadOptions& options);
int run_road(const RoadOptions& options);

}  // namespace rollnoise

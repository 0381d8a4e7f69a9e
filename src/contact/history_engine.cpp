#include "contact/history_engine.hpp"

#include "contact/direct_history_engine.hpp"
#include "core/error.hpp"

namespace rollnoise {

HistoryKind parse_history_kind(const std::string& name) {
  if (name == "auto") return HistoryKind::automatic;
  if (name == "direct") return HistoryKind::direct;
  if (name == "modal") return HistoryKind::modal;
  throw std::invalid_argument("unknown history engine \"" + name + "\"");
}

std::string to_string(HistoryKind kind) {
  switch (kind) {
    case HistoryKind::automatic: return "auto";
    case HistoryKind::direct: return "direct";
    case HistoryKind::modal: return "modal";
  }
  return "?";
}

std::unique_ptr<HistoryEngine> make_history_engine(HistoryKind kind,
                                                   std::shared_ptr<const DiscreteKernel> kernel,
                                                   std::size_t steps,
                                                   const Eigen::VectorXd& preload) {
  switch (kind) {
    case HistoryKind::automatic:
    case HistoryKind::direct:
      return std::make_unique<DirectHistoryEngine>(std::move(kernel), steps, preload);
    case HistoryKind::modal:
      break;
  }
  throw InputError("", "[rolling] history",
                   "engine \"" + to_string(kind) +
                       "\" is not available for the point models; allowed: \"auto\", \"direct\"");
}

}  // namespace rollnoise

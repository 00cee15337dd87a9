// The model ids as names: for "did you mean" suggestions and the one unknown-model message.
#pragma once
#include <string>
#include <vector>

namespace kiln {

/// Every model id, BRDFs (AllModels) then BSDFs (AllBsdfModels): the names "did you mean"
/// suggestions pick from.
std::vector<std::string> AllModelIds();

/// "unknown model 'ID' (did you mean 'CLOSEST'?) (see `kiln list`)", the suggestion only when
/// an id is close (DidYouMean): the one message for an unknown model id.
std::string UnknownModelMessage(const std::string& id);

}  // namespace kiln

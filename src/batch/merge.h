#pragma once
// Combining the folders of shards (or of separate machines) into one (SPEC section 7): the
// run files copied whole, the manifests' scenes united, the timings kept. The summary and
// report are then written from the combined folder as for one process, with the same bytes.
#include <string>
#include <vector>

#include "records/batch_folder.h"

namespace camcov::batch {

// InputError if an input is no batch folder, holds a damaged run, or was made with other
// parameters or by other code of a method than the first; then nothing has been written.
// `target` may be one of the inputs. Returns the combined manifest (also written).
records::BatchManifest mergeFolders(const std::vector<std::string>& inputs,
                                    const records::BatchFolder& target,
                                    const std::vector<std::string>& command);

}  // namespace camcov::batch

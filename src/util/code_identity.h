#pragma once
// The identity of the code that makes a run's numbers: a hash of every source file of the
// stages from the scene to the simulator and of the methods a build brings (examples/),
// taken at build time (cmake/code_identity.cmake). A batch records it for each C++ method, so
// results made by other code are never resumed as if they were this build's.
namespace camcov {

// 16 hex digits; the same sources give the same identity on every machine.
const char* codeIdentity();

}  // namespace camcov

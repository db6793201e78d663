// ir_module.cc - mdlc/ir.h: the IR module behind a Result.
#include "mdlc/ir.h"

#include "tools/driver/result_access.h"

namespace mdlc {

const ir::Module& IrModule(const Result& result) {
  return ResultAccess::compilation(result).module;
}

}  // namespace mdlc

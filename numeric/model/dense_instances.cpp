// The explicit instantiations dense_instances.hpp declares extern everywhere else.
#include "numeric/model/dense_instances.hpp"

SCALCAL_DENSE_INSTANCES()

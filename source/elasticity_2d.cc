// One dimension per translation unit: the two instantiations compile in
// parallel and a change to the template rebuilds both at once.
#include <xcrack/elasticity.templates.h>

template class xcrack::ElasticityProblem<2>;

/* faultyBungee: the example connector examples/customConnector/bungee.c,
   unchanged, with a fault inside fmi2DoStep: the first step from
   t = FAULT_TIME on (0.25 s unless defined) does what FAULT_<KIND> says
   instead of stepping, for the reliability tests of fmusim and the bridge
   (a connector written by a third party that misbehaves):

       FAULT_SEGFAULT        writes through a null pointer (SIGSEGV)
       FAULT_DIVIDE_BY_ZERO  divides an integer by zero (SIGFPE, whatever
                             the floating-point traps)
       FAULT_ABORT           calls abort() (SIGABRT)
       FAULT_HANG            never returns
       FAULT_EXIT            calls exit(0): the process ends "successfully"

   The example's fmi2DoStep is renamed before its file is included, and
   called when no fault is due. */
#define fmi2DoStep bungeeDoStep
#include "bungee.c"
#undef fmi2DoStep

#ifndef FAULT_TIME
#define FAULT_TIME 0.25
#endif

static void fault(void)
{
#if defined(FAULT_SEGFAULT)
    /* volatile all through, or the compiler may drop the store */
    volatile int* volatile nowhere = NULL;
    *nowhere = 1;
#elif defined(FAULT_DIVIDE_BY_ZERO)
    /* neither operand known, or the compiler computes 1 / x without idiv */
    volatile int one = 1, zero = 0;
    volatile int quotient = one / zero;
    (void)quotient;
#elif defined(FAULT_ABORT)
    abort();
#elif defined(FAULT_HANG)
    volatile int spinning = 1;
    while (spinning) { }
#elif defined(FAULT_EXIT)
    exit(0);
#else
#error                                                                         \
    "define one of FAULT_SEGFAULT, FAULT_DIVIDE_BY_ZERO, FAULT_ABORT, FAULT_HANG, FAULT_EXIT"
#endif
}

FMI2_Export fmi2DoStepTYPE fmi2DoStep;

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint)
{
    if (currentCommunicationPoint >= FAULT_TIME)
        fault();
    return bungeeDoStep(c, currentCommunicationPoint, communicationStepSize,
                        noSetFMUStatePriorToCurrentPoint);
}

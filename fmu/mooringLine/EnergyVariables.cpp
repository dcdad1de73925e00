#include "EnergyVariables.hpp"

#include <string>

namespace mooringLineFmu {

namespace energyVariables {

namespace {

using fmuExport::lineSections::Variable;

const char* const since = " since fmi2ExitInitializationMode";

//- A section's share of a whole-line value
struct PerSection {
    const char* name;
    const char* description;
};

const PerSection perSection[] = {
    {"kineticEnergy",
     "kinetic energy of section #'s free nodes (v' M v / 2, "
     "added mass included; a joint's node in the section "
     "above it)"},
    {"dragDissipated",
     "energy dissipated by the drag on section # (relative "
     "to the water)"},
    {"seabedDissipated",
     "energy dissipated by the seabed under section # "
     "(penalty damping, friction)"},
    {"axialDissipated", "energy dissipated by section #'s axial damping"},
};

} // namespace

std::vector<Variable> outputs(int sections)
{
    std::vector<Variable> v = {
        {"kineticEnergy", "J",
         "kinetic energy of the line's free nodes, v' M v / 2 with the added "
         "mass about each node's tangent"},
        {"fairleadWork", "J",
         std::string("work done on the line by A at the fairlead A.p") + since},
        {"anchorWork", "J",
         std::string("work done on the line by B at B.p") + since
             + " (0 for an anchor held still)"},
        {"waterWork", "J",
         std::string("work done on the line by the moving water (the drag's "
                     "share from the current and the flow inputs, the "
                     "flow's inertia)")
             + since + "; 0 in still water"},
        {"addedMassWork", "J",
         std::string("work of the added mass turning with the line (the node "
                     "equations M(x) a = F leave out d(M v)/dt - M a; 0 "
                     "without added mass or free surface)")
             + since},
        {"dissipatedEnergy", "J",
         std::string("energy dissipated by the line") + since
             + ": dragDissipated + seabedDissipated + axialDissipated; "
               "fairleadWork + anchorWork + waterWork + addedMassWork = "
               "kineticEnergy + potentialEnergy + dissipatedEnergy - their "
               "start values"},
        {"dragDissipated", "J",
         std::string("energy dissipated by the drag (relative to the water)")
             + since},
        {"seabedDissipated", "J",
         std::string("energy dissipated by the seabed (penalty damping, "
                     "friction)")
             + since},
        {"axialDissipated", "J",
         std::string("energy dissipated by the axial damping") + since},
    };
    for (const PerSection& s : perSection) {
        for (int k = 1; k <= sections; ++k) {
            const std::string n = std::to_string(k);
            std::string description = s.description;
            description.replace(description.find('#'), 1, n);
            if (s.name != std::string("kineticEnergy")) {
                description += since;
            }
            v.push_back({std::string("section.") + s.name + "[" + n + "]", "J",
                         description + "; 0 without section " + n});
        }
    }
    return v;
}

std::vector<double> values(const connectors::MooringLineOutput& m,
                           const connectors::LineEnergy& total, int sections)
{
    std::vector<double> v
        = {m.kineticEnergy,   total.fairlead,      total.anchor,
           total.water,       total.addedMass,     total.dissipated(),
           total.dragTotal(), total.seabedTotal(), total.axialTotal()};
    for (const std::vector<double>* x :
         {&m.sectionKineticEnergy, &total.drag, &total.seabed, &total.axial}) {
        for (int k = 0; k < sections; ++k) {
            v.push_back(std::size_t(k) < x->size() ? (*x)[std::size_t(k)]
                                                   : 0.0);
        }
    }
    return v;
}

} // namespace energyVariables

} // namespace mooringLineFmu

// A connector FMU's inputs and outputs as fmusim drives them: two bodies'
// kinematics and mass properties in, loads out. The interface's vocabulary
// and rules are fmuImport's (fmuImport::connector).
#ifndef FMUSIM_IO_CONNECTORIO_HPP
#define FMUSIM_IO_CONNECTORIO_HPP

#include "fmuImport/fmuImport.hpp"

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace fmusim {

// Kinematics of a body's reference point, global frame (the world's are the
// defaults).
struct Kinematics {
    Eigen::Vector3d r = Eigen::Vector3d::Zero(); // position [m]
    Eigen::Matrix3d R
        = Eigen::Matrix3d::Identity(); // orientation, body to global [-]
    Eigen::Vector3d v = Eigen::Vector3d::Zero(); // velocity [m/s]
    Eigen::Vector3d omega = Eigen::Vector3d::Zero(); // angular velocity [rad/s]
};

struct MassProperties {
    double m = 1; // mass [kg]
    Eigen::Vector3d c = Eigen::Vector3d::
        Zero(); // centre of mass from the reference point, body frame [m]
    Eigen::Matrix3d J = Eigen::Matrix3d::
        Identity(); // inertia about the centre of mass, body frame [kg.m2]
};

struct Loads {
    Eigen::Vector3d F = Eigen::Vector3d::Zero(); // force [N]
    Eigen::Vector3d M
        = Eigen::Vector3d::Zero(); // moment about the reference point [N.m]
};

// A connector FMU's kinematic inputs, mass property inputs and load outputs
// as Eigen vectors, set and read through the value references of its
// interface variables (fmuImport::connector::Variables).
class ConnectorIo {
public:
    explicit ConnectorIo(const fmuImport::Fmu& fmu);

    // The FMU's interface variables: whether it is a two-body connector,
    // the required terms it lacks, its departures from the interface
    const fmuImport::connector::Variables& variables() const
    {
        return variables_;
    }

    // Declares the loads on B (B.F and B.M).
    bool hasLoadsB() const
    {
        return variables_.declared("B.F") && variables_.declared("B.M");
    }

    // Sets the declared inputs; for a one-body connector B is ignored.
    void setKinematics(fmuImport::Instance& instance, const Kinematics& A,
                       const Kinematics& B) const;
    void setMassProperties(fmuImport::Instance& instance,
                           const MassProperties& A,
                           const MassProperties& B) const;

    // Loads on A and B (zero for B when B.F, B.M are not declared).
    void getLoads(fmuImport::Instance& instance, Loads& A, Loads& B) const;

    // The names and value references of the declared kinematic inputs, for
    // probing.
    std::vector<std::pair<std::string, unsigned int>> kinematicInputs() const;

private:
    fmuImport::connector::Variables variables_;
};

} // namespace fmusim

#endif

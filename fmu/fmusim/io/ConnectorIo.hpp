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

// A connector FMU's kinematic inputs, mass property inputs and load outputs,
// by value reference (declared terms of fmuImport::connector::Variables).
class ConnectorIo {
public:
    explicit ConnectorIo(const fmuImport::Fmu& fmu);

    // The FMU's interface variables and their departures from the interface
    const fmuImport::connector::Variables& variables() const
    {
        return variables_;
    }

    bool twoBody() const { return variables_.twoBody(); } // declares B. inputs
    // The required terms not fully declared ("A.F", ...); empty for a
    // usable connector.
    std::vector<std::string> missingRequired() const
    {
        return variables_.missingRequired();
    }
    bool hasLoadsB() const { return !B_.F.empty() && !B_.M.empty(); }
    bool hasVelocities() const
    {
        return !A_.v.empty() || !A_.omega.empty() || !B_.v.empty()
            || !B_.omega.empty();
    }

    // Sets the declared inputs; for a one-body connector B is ignored.
    void setKinematics(fmuImport::Instance& instance, const Kinematics& A,
                       const Kinematics& B) const;
    void setMassProperties(fmuImport::Instance& instance,
                           const MassProperties& A,
                           const MassProperties& B) const;

    // Loads on A and B (zero for B when B.F, B.M are not declared).
    void getLoads(fmuImport::Instance& instance, Loads& A, Loads& B) const;

    // The value references of the declared kinematic inputs, for probing.
    std::vector<std::pair<std::string, unsigned int>> kinematicInputs() const;

private:
    // Value references of one body's terms, empty when not declared
    struct Body {
        std::vector<unsigned int> r, R, v, omega, m, c, J, F, M;
    };

    Body body(const std::string& prefix) const;

    fmuImport::connector::Variables variables_;
    Body A_, B_;
};

} // namespace fmusim

#endif

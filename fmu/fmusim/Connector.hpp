// The connector FMU interface (docs/connector-fmu-interface.md) seen from
// fmusim: its vocabulary of variables, and feeding two bodies' kinematics to
// a connector instance and reading back the loads.
#ifndef FMUSIM_CONNECTOR_HPP
#define FMUSIM_CONNECTOR_HPP

#include "WatchedInstance.hpp"

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

enum class Shape { scalar, vector, matrix };
enum class Requirement { always, twoBody, optional };

// One name of the interface: base "A.r" with shape vector stands for
// A.r[1], A.r[2], A.r[3].
struct VocabularyEntry {
    std::string base;
    Shape shape;
    fmuImport::Causality causality;
    fmuImport::Variability variability;
    std::vector<std::string>
        units; // accepted units; the first is the documented one
    Requirement requirement;
};

const std::vector<VocabularyEntry>& connectorVocabulary();

// The scalar names of an entry: "A.r[1]".."A.r[3]", "A.R[1,1]".."A.R[3,3]".
std::vector<std::string> componentNames(const std::string& base, Shape shape);

// A connector FMU's kinematic inputs, mass property inputs and load outputs,
// by value reference. A block counts as declared when all its components are
// declared Real variables.
class Connector {
public:
    explicit Connector(const fmuImport::Fmu& fmu);

    bool twoBody() const { return twoBody_; } // declares B. inputs
    // The required blocks not fully declared ("A.F", ...); empty for a
    // usable connector.
    std::vector<std::string> missingRequired() const;
    bool hasLoadsB() const { return B_.F.declared && B_.M.declared; }
    bool hasVelocities() const
    {
        return A_.v.declared || A_.omega.declared || B_.v.declared
            || B_.omega.declared;
    }

    // Sets the declared inputs; for a one-body connector B is ignored.
    void setKinematics(WatchedInstance& instance, const Kinematics& A,
                       const Kinematics& B) const;
    void setMassProperties(WatchedInstance& instance, const MassProperties& A,
                           const MassProperties& B) const;

    // Loads on A and B (zero for B when B.F, B.M are not declared).
    void getLoads(WatchedInstance& instance, Loads& A, Loads& B) const;

    // The value references of the declared kinematic inputs, for probing.
    std::vector<std::pair<std::string, unsigned int>> kinematicInputs() const;

private:
    struct Block {
        std::vector<std::string> names;
        std::vector<unsigned int> vrs;
        bool declared = false;
    };
    struct Body {
        Block r, R, v, omega, m, c, J, F, M;
    };

    static Block find(const fmuImport::Fmu& fmu, const std::string& base,
                      Shape shape);
    static Body findBody(const fmuImport::Fmu& fmu, const std::string& prefix);

    Body A_, B_;
    bool twoBody_ = false;
};

} // namespace fmusim

#endif

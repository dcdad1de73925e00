// LawFmuModel: a connector model whose law is built from one parameter
// struct (p_AoP_A, p_BoQ_B and the law's own fields). Each parameter is
// declared once, bound to its field: setParameters fills the struct from
// the value array (A.p and B.p as p_AoP_A and p_BoQ_B) and builds the law,
// and evaluate returns the law's result unless the model overrides it.
#ifndef FMU_EXPORT_LAWFMUMODEL_HPP
#define FMU_EXPORT_LAWFMUMODEL_HPP

#include <string>
#include <utility>
#include <vector>

#include "ConnectorFmuModel.hpp"

namespace fmuExport {

template <class Law, class Parameters>
class LawFmuModel : public ConnectorFmuModel {
public:
    void setParameters(const double* values) override
    {
        Parameters p;
        p.p_AoP_A = vector3(values, A_p);
        p.p_BoQ_B = vector3(values, B_p);
        for (const auto& [field, block] : vectors_) {
            p.*field = vector3(values, block);
        }
        for (const auto& [field, block] : scalars_) {
            p.*field = scalar(values, block);
        }
        for (const auto& [field, block] : matrices_) {
            readBlockMatrix3(values, block, p.*field);
        }
        setOtherParameters(values, p);
        law_.build(p);
    }

protected:
    using ConnectorFmuModel::ConnectorFmuModel;

    //- Declares a scalar parameter (VariableTable::parameter) whose value
    //  becomes `field` of the law's parameters
    Block parameter(double Parameters::*field, const std::string& name,
                    const std::string& unit, const std::string& description,
                    double start)
    {
        const Block block = table().parameter(name, Shape::scalar, unit,
                                              description, {start});
        scalars_.emplace_back(field, block);
        return block;
    }

    //- Declares a vector parameter whose value becomes `field`
    Block parameter(connectors::Vector3 Parameters::*field,
                    const std::string& name, const std::string& unit,
                    const std::string& description,
                    const std::vector<double>& start)
    {
        const Block block
            = table().parameter(name, Shape::vector3, unit, description, start);
        vectors_.emplace_back(field, block);
        return block;
    }

    //- Declares a 3x3 parameter (name[i,j], start row by row) whose value
    //  becomes `field`
    Block parameter(connectors::Matrix3 Parameters::*field,
                    const std::string& name, const std::string& unit,
                    const std::string& description,
                    const std::vector<double>& start)
    {
        const Block block
            = table().parameter(name, Shape::matrix3, unit, description, start);
        matrices_.emplace_back(field, block);
        return block;
    }

    //- Declares the angular springs' referenceOrientation (the identity by
    //  default), whose value becomes the law's R_BA0
    Block referenceOrientation()
    {
        return parameter(
            &Parameters::R_BA0, "referenceOrientation", "1",
            "reference orientation of A relative to B, A's frame to B's",
            {1, 0, 0, 0, 1, 0, 0, 0, 1});
    }

    //- Sets the fields of p that are no scalar, vector or 3x3 parameter (a
    //  table), from the value array, after those and before the law is
    //  built; none here
    virtual void setOtherParameters(const double*, Parameters&) const { }

    ConnectorOutputs
    evaluate(const double*, const connectors::BodyKinematics& A,
             const connectors::BodyKinematics& B) const override
    {
        return law_.get().evaluate(A, B);
    }

    //- The law built by the last setParameters
    const Law& law() const { return law_.get(); }

private:
    std::vector<std::pair<connectors::Matrix3 Parameters::*, Block>> matrices_;
    std::vector<std::pair<connectors::Vector3 Parameters::*, Block>> vectors_;
    std::vector<std::pair<double Parameters::*, Block>> scalars_;
    BuiltLaw<Law> law_;
};

} // namespace fmuExport

#endif

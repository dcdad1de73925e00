// movingSlipWallVelocity: a slip wall that moves with the mesh (built by
// bench/peers/lightBodyCompare into its work folder): the normal velocity the wall's,
// as movingWallVelocity gives it, the tangential one the fluid's
#include "movingWallVelocityFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{

class movingSlipWallVelocityFvPatchVectorField
:
    public movingWallVelocityFvPatchVectorField
{
public:

    TypeName("movingSlipWallVelocity");

    movingSlipWallVelocityFvPatchVectorField
    (
        const fvPatch& p,
        const DimensionedField<vector, volMesh>& iF
    )
    :
        movingWallVelocityFvPatchVectorField(p, iF)
    {}

    movingSlipWallVelocityFvPatchVectorField
    (
        const fvPatch& p,
        const DimensionedField<vector, volMesh>& iF,
        const dictionary& dict
    )
    :
        movingWallVelocityFvPatchVectorField(p, iF, dict)
    {}

    movingSlipWallVelocityFvPatchVectorField
    (
        const movingSlipWallVelocityFvPatchVectorField& ptf,
        const fvPatch& p,
        const DimensionedField<vector, volMesh>& iF,
        const fvPatchFieldMapper& mapper
    )
    :
        movingWallVelocityFvPatchVectorField(ptf, p, iF, mapper)
    {}

    movingSlipWallVelocityFvPatchVectorField
    (
        const movingSlipWallVelocityFvPatchVectorField& ptf
    )
    :
        movingWallVelocityFvPatchVectorField(ptf)
    {}

    movingSlipWallVelocityFvPatchVectorField
    (
        const movingSlipWallVelocityFvPatchVectorField& ptf,
        const DimensionedField<vector, volMesh>& iF
    )
    :
        movingWallVelocityFvPatchVectorField(ptf, iF)
    {}

    virtual tmp<fvPatchVectorField> clone() const
    {
        return tmp<fvPatchVectorField>
        (
            new movingSlipWallVelocityFvPatchVectorField(*this)
        );
    }

    virtual tmp<fvPatchVectorField> clone
    (
        const DimensionedField<vector, volMesh>& iF
    ) const
    {
        return tmp<fvPatchVectorField>
        (
            new movingSlipWallVelocityFvPatchVectorField(*this, iF)
        );
    }

    virtual void updateCoeffs()
    {
        if (updated())
        {
            return;
        }

        const vectorField n(patch().nf());
        vectorField Up(patchInternalField());
        Up -= n*(n & Up);
        if (internalField().mesh().moving())
        {
            Up += n*(n & Uwall());
        }
        vectorField::operator=(Up);

        fixedValueFvPatchVectorField::updateCoeffs();
    }
};

makePatchTypeField
(
    fvPatchVectorField,
    movingSlipWallVelocityFvPatchVectorField
);

} // End namespace Foam

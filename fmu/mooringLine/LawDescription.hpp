// The law's description in mooringLine.fmu's modelDescription.xml (HTML,
// the documentation's first page).
#ifndef FMU_MOORINGLINE_LAWDESCRIPTION_HPP
#define FMU_MOORINGLINE_LAWDESCRIPTION_HPP

namespace mooringLineFmu {

extern const char* const lawHtml;

} // namespace mooringLineFmu

#endif

#include "stackbook/output/contacts_csv.hpp"

#include "stackbook/output/csv.hpp"
#include "stackbook/output/output_files.hpp"

namespace stackbook {

template <int D>
void writeContactsCsv(const Recording<D>& recording, const std::string& path) {
  using output_detail::exactDecimal;
  std::string csv = D == 2 ? "frame,time,stage,bodyA,nameA,bodyB,nameB,x,y,nx,ny,jx,jy\n"
                           : "frame,time,stage,bodyA,nameA,bodyB,nameB,x,y,z,nx,ny,nz,jx,jy,jz\n";
  const auto& visuals = recording.visuals();
  const auto name = [&visuals](int body) {
    return body >= 0 && static_cast<std::size_t>(body) < visuals.size()
               ? csvField(visuals[static_cast<std::size_t>(body)].name)
               : std::string();
  };
  for (const RecordedContact& rc : recording.contacts()) {
    const ContactRecord& c = rc.contact;
    csv += std::to_string(rc.frame);
    csv += ',';
    csv += exactDecimal(rc.time);
    csv += ',';
    csv += contactStageName(c.stage);
    csv += ',' + std::to_string(c.owner) + ',' + name(c.owner);
    csv += ',' + std::to_string(c.other) + ',' + name(c.other);
    for (const auto* v : {&c.point, &c.normal, &c.impulse}) {
      for (int k = 0; k < D; ++k) {
        csv += ',';
        csv += exactDecimal((*v)[static_cast<std::size_t>(k)]);
      }
    }
    csv += '\n';
  }
  output_detail::writeFileOrThrow("writeContactsCsv", path, csv);
}

template void writeContactsCsv<2>(const Recording<2>&, const std::string&);
template void writeContactsCsv<3>(const Recording<3>&, const std::string&);

}  // namespace stackbook

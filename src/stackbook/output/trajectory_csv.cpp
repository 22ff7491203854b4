#include "stackbook/output/trajectory_csv.hpp"

#include "stackbook/output/csv.hpp"
#include "stackbook/output/output_files.hpp"

namespace stackbook {

template <int D>
void writeTrajectoryCsv(const Recording<D>& recording, const std::string& path) {
  using output_detail::exactDecimal;
  std::string csv = D == 2 ? "time,body,name,x,y,angle,vx,vy,omega\n"
                           : "time,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n";
  const auto& visuals = recording.visuals();
  for (std::size_t f = 0; f < recording.frameCount(); ++f) {
    const std::string time = exactDecimal(recording.times()[f]);
    for (std::size_t i = 0; i < recording.bodyCount(); ++i) {
      const Pose<D>& pose = recording.poses()[f][i];
      csv += time;
      csv += ',';
      csv += std::to_string(i);
      csv += ',';
      csv += csvField(visuals[i].name);
      for (int k = 0; k < D; ++k) {
        csv += ',';
        csv += exactDecimal(pose.position[k]);
      }
      if constexpr (D == 2) {
        csv += ',';
        csv += exactDecimal(pose.orientation.angle());
      } else {
        const Eigen::Quaterniond& q = pose.orientation;
        for (double c : {q.w(), q.x(), q.y(), q.z()}) {
          csv += ',';
          csv += exactDecimal(c);
        }
      }
      const Vec<D>& v = recording.velocities()[f][i];
      for (int k = 0; k < D; ++k) {
        csv += ',';
        csv += exactDecimal(v[k]);
      }
      const AngVec<D>& omega = recording.angularVelocities()[f][i];
      for (int k = 0; k < omega.size(); ++k) {
        csv += ',';
        csv += exactDecimal(omega[k]);
      }
      csv += '\n';
    }
  }
  output_detail::writeFileOrThrow("writeTrajectoryCsv", path, csv);
}

template void writeTrajectoryCsv<2>(const Recording<2>&, const std::string&);
template void writeTrajectoryCsv<3>(const Recording<3>&, const std::string&);

template <int D>
void writeEnergyCsv(const Recording<D>& recording, const std::string& path) {
  using output_detail::exactDecimal;
  std::string csv = "time,kinetic,potential,total\n";
  for (std::size_t f = 0; f < recording.frameCount(); ++f) {
    const FrameEnergy& e = recording.energies()[f];
    csv += exactDecimal(recording.times()[f]) + ',' + exactDecimal(e.kinetic) + ',' +
           exactDecimal(e.potential) + ',' + exactDecimal(e.total()) + '\n';
  }
  output_detail::writeFileOrThrow("writeEnergyCsv", path, csv);
}

template void writeEnergyCsv<2>(const Recording<2>&, const std::string&);
template void writeEnergyCsv<3>(const Recording<3>&, const std::string&);

}  // namespace stackbook

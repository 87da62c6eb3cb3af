#include <softgrasp/mujoco/link_forces.h>

namespace softgrasp
{
  std::vector<LinkContactForce>
  link_contact_forces(const mjModel          *m,
                      const mjData           *d,
                      const int               object_body,
                      const std::vector<int> &geoms)
  {
    std::vector<LinkContactForce> result(geoms.size());
    for (int c = 0; c < d->ncon; ++c)
    {
      const mjContact &contact = d->contact[c];
      const int        g1 = contact.geom1, g2 = contact.geom2;
      const bool       object1 = m->geom_bodyid[g1] == object_body;
      const bool       object2 = m->geom_bodyid[g2] == object_body;
      if (object1 == object2)
        continue; // not a contact between the object and something else
      const int link = object1 ? g2 : g1;
      for (std::size_t i = 0; i < geoms.size(); ++i)
      {
        if (geoms[i] != link)
          continue;
        mjtNum local[6];
        mj_contactForce(m, d, c, local);
        // Rows of the frame: normal (geom1 -> geom2), tangent 1, tangent 2.
        Eigen::Vector3d rows[3];
        for (int r = 0; r < 3; ++r)
          rows[r] = Eigen::Vector3d(contact.frame[3 * r],
                                    contact.frame[3 * r + 1],
                                    contact.frame[3 * r + 2]);
        // Force on geom2 in world coordinates; the link may be geom1.
        const double    sign = (link == g2) ? 1.0 : -1.0;
        Eigen::Vector3d f    = Eigen::Vector3d::Zero();
        for (int r = 0; r < 3; ++r)
          f += local[r] * rows[r];
        f *= sign;
        result[i].force += f;
        result[i].normal_force += rows[0] * rows[0].dot(f);
        ++result[i].n_contacts;
      }
    }
    for (auto &r : result)
      if (r.normal_force.norm() > 0)
        r.normal = r.normal_force.normalized();
    return result;
  }
} // namespace softgrasp

#include <Eigen/Geometry>
#include <algorithm>
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

  namespace
  {
    /// Velocity (world) of the point @p p fixed to body @p b.
    Eigen::Vector3d point_velocity(const mjModel         *m,
                                   const mjData          *d,
                                   const int              b,
                                   const Eigen::Vector3d &p)
    {
      mjtNum v[6]; // rotation, then translation at the body's centre of mass
      mj_objectVelocity(m, d, mjOBJ_BODY, b, v, 0);
      const Eigen::Vector3d omega(v[0], v[1], v[2]), linear(v[3], v[4], v[5]);
      const Eigen::Vector3d centre(
          d->xipos[3 * b], d->xipos[3 * b + 1], d->xipos[3 * b + 2]);
      return linear + omega.cross(p - centre);
    }
  } // namespace

  std::vector<double> link_slip_speeds(const mjModel          *m,
                                       const mjData           *d,
                                       const int               object_body,
                                       const std::vector<int> &geoms)
  {
    std::vector<double> speed(geoms.size(), 0), weight(geoms.size(), 0);
    for (int c = 0; c < d->ncon; ++c)
    {
      const mjContact &contact = d->contact[c];
      const bool       object1 = m->geom_bodyid[contact.geom1] == object_body;
      const bool       object2 = m->geom_bodyid[contact.geom2] == object_body;
      if (object1 == object2)
        continue;
      const int  link = object1 ? contact.geom2 : contact.geom1;
      const auto it   = std::find(geoms.begin(), geoms.end(), link);
      if (it == geoms.end())
        continue;
      mjtNum local[6];
      mj_contactForce(m, d, c, local);
      const Eigen::Vector3d p(contact.pos[0], contact.pos[1], contact.pos[2]);
      const Eigen::Vector3d n(
          contact.frame[0], contact.frame[1], contact.frame[2]);
      const Eigen::Vector3d relative =
          point_velocity(m, d, m->geom_bodyid[link], p) -
          point_velocity(m, d, object_body, p);
      const double w = std::abs(local[0]);
      const auto   i = it - geoms.begin();
      speed[i] += w * (relative - n * n.dot(relative)).norm();
      weight[i] += w;
    }
    for (std::size_t i = 0; i < geoms.size(); ++i)
      speed[i] = weight[i] > 0 ? speed[i] / weight[i] : 0;
    return speed;
  }
} // namespace softgrasp

// Format version 1's predictions (schema/FORMAT.md, "Chunk columns, version 1"), frozen with that version:
// v_j' from momentum conservation, and a wall's perfect reflection. Includes only the standard library.
#pragma once

namespace ede::rules::v1 {

// ((m_i v_i + m_j v_j) - m_i v_i') / m_j, per component.
template <class T>
inline T momentum_prediction(T mi, T mj, T vi0, T vj0, T vi1) {
  return ((mi * vi0 + mj * vj0) - mi * vi1) / mj;
}

}  // namespace ede::rules::v1

#include "renderer.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>

#include <limits>
#include <stdexcept>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace viewer::detail {

namespace {

const Eigen::Vector3f kBackground(0.91f, 0.93f, 0.95f);
const Eigen::Vector3f kCollisionColour(0.95f, 0.55f, 0.15f);
const Eigen::Vector3f kSoftColour(0.85f, 0.25f, 0.30f);

void lights(float brightness) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_LIGHT1);
  glEnable(GL_NORMALIZE);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  const GLfloat key[] = {0.4f, 0.3f, 1.0f, 0.0f}, fill[] = {-0.5f, -0.6f, 0.3f, 0.0f};
  const float b = brightness;
  const GLfloat key_colour[] = {0.75f * b, 0.75f * b, 0.72f * b, 1.0f},
                fill_colour[] = {0.3f * b, 0.3f * b, 0.35f * b, 1.0f};
  const GLfloat ambient[] = {0.25f * b, 0.25f * b, 0.25f * b, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, key);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, key_colour);
  glLightfv(GL_LIGHT1, GL_POSITION, fill);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, fill_colour);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
}

void triangles(const TriangleMesh& m) {
  if (m.positions.empty()) return;
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, sizeof(Eigen::Vector3f), m.positions.data());
  glNormalPointer(GL_FLOAT, sizeof(Eigen::Vector3f), m.normals.data());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(m.positions.size()));
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

void colour(const Eigen::Vector3f& c) {
  glColor3f(c.x(), c.y(), c.z());
}

void softBody(const SoftGeometry& g, const std::vector<Eigen::Vector3f>& nodes,
              const Eigen::Vector3f& tint) {
  colour(kSoftColour.cwiseProduct(tint));
  if (!g.faces.empty()) {
    glBegin(GL_TRIANGLES);
    for (const auto& f : g.faces) {
      const auto &a = nodes[f[0]], &b = nodes[f[1]], &c = nodes[f[2]];
      const Eigen::Vector3f n = (b - a).cross(c - a).normalized();
      glNormal3fv(n.data());
      glVertex3fv(a.data());
      glVertex3fv(b.data());
      glVertex3fv(c.data());
    }
    glEnd();
    return;
  }
  glDisable(GL_LIGHTING);
  glBegin(GL_LINES);
  for (const auto& l : g.links) {
    glVertex3fv(nodes[l[0]].data());
    glVertex3fv(nodes[l[1]].data());
  }
  glEnd();
  glEnable(GL_LIGHTING);
}

void contacts(const std::vector<ambf_like::Contact>& list, double scale) {
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glPointSize(6.0f);
  glColor3f(0.1f, 0.6f, 0.1f);
  glBegin(GL_POINTS);
  for (const auto& c : list) glVertex3dv(c.position_on_b.data());
  glEnd();
  glBegin(GL_LINES);
  for (const auto& c : list) {
    glVertex3dv(c.position_on_b.data());
    const Eigen::Vector3d tip = c.position_on_b + scale * c.normal_on_b;
    glVertex3dv(tip.data());
  }
  glEnd();
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
}

/// Clears to `background`, sets the camera's projection and view (the lights, at `brightness`
/// unless 0, in eye coordinates: they move with the camera).
void frameUp(const Camera& camera, int width, int height, const Eigen::Vector3f& background,
             float brightness) {
  glViewport(0, 0, width, height);
  glClearColor(background.x(), background.y(), background.z(), 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  const Eigen::Matrix4d projection = camera.projection(static_cast<double>(width) / height);
  glLoadMatrixd(projection.data());
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  if (brightness > 0.0f) {
    lights(brightness);
  } else {
    glDisable(GL_LIGHTING);
  }
  const Eigen::Matrix4d v = camera.view();
  glLoadMatrixd(v.data());
}

Eigen::Vector3f labelColour(std::uint32_t id) {
  return Eigen::Vector3f(static_cast<float>(id & 0xff), static_cast<float>((id >> 8) & 0xff),
                         static_cast<float>((id >> 16) & 0xff)) /
         255.0f;
}

}  // namespace

void drawLabels(const SceneGeometry& scene, const FrameState& frame, const Camera& camera,
                int width, int height, const SceneLabels& labels) {
  frameUp(camera, width, height, Eigen::Vector3f::Zero(), 0.0f);
  for (std::size_t i = 0; i < scene.bodies.size() && i < frame.body_poses.size(); ++i) {
    const TriangleMesh& mesh = scene.bodies[i].visual;
    const std::vector<std::uint32_t>& ids = labels.bodies.at(i);
    glPushMatrix();
    glMultMatrixd(frame.body_poses[i].matrix().data());
    glBegin(GL_TRIANGLES);
    for (std::size_t t = 0; t < mesh.triangles(); ++t) {
      glColor3fv(labelColour(ids.size() == 1 ? ids[0] : ids.at(t)).data());
      for (std::size_t k = 0; k < 3; ++k) glVertex3fv(mesh.positions[3 * t + k].data());
    }
    glEnd();
    glPopMatrix();
  }
  for (std::size_t i = 0; i < scene.soft_bodies.size() && i < frame.soft_nodes.size(); ++i) {
    glColor3fv(labelColour(labels.soft_bodies.at(i)).data());
    const auto& nodes = frame.soft_nodes[i];
    glBegin(GL_TRIANGLES);
    for (const auto& f : scene.soft_bodies[i].faces) {
      for (int k : f) glVertex3fv(nodes[static_cast<std::size_t>(k)].data());
    }
    glEnd();
  }
  glEnable(GL_LIGHTING);
}

std::vector<float> readDepth(const Camera& camera, int width, int height) {
  std::vector<float> depth(static_cast<std::size_t>(width) * height);
  glFinish();
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  // The window depth back to the distance along the axis (a perspective projection).
  const double n = camera.nearPlane(), f = camera.farPlane();
  for (float& d : depth) {
    if (d >= 1.0f) {
      d = std::numeric_limits<float>::infinity();
      continue;
    }
    const double ndc = 2.0 * d - 1.0;
    d = static_cast<float>(2.0 * n * f / (f + n - ndc * (f - n)));
  }
  const std::size_t row = static_cast<std::size_t>(width);
  for (int y = 0; y < height / 2; ++y) {
    std::swap_ranges(depth.begin() + y * row, depth.begin() + (y + 1) * row,
                     depth.begin() + (height - 1 - y) * row);
  }
  return depth;
}

void draw(const SceneGeometry& scene, const FrameState& frame, const Camera& camera, int width,
          int height, const ViewOptions& view, const Look& look) {
  frameUp(camera, width, height, kBackground, look.light);
  for (std::size_t i = 0; i < scene.bodies.size() && i < frame.body_poses.size(); ++i) {
    const BodyGeometry& body = scene.bodies[i];
    glPushMatrix();
    glMultMatrixd(frame.body_poses[i].matrix().data());
    if (view.collision) {
      colour(kCollisionColour);
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(1.0f, 1.0f);
      triangles(body.collision);
      glDisable(GL_POLYGON_OFFSET_FILL);
      glDisable(GL_LIGHTING);
      glColor3f(0.25f, 0.12f, 0.0f);
      glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
      triangles(body.collision);
      glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
      glEnable(GL_LIGHTING);
    } else {
      colour(body.colour.cwiseProduct(look.body_tint));
      triangles(body.visual);
    }
    glPopMatrix();
  }
  for (std::size_t i = 0; i < scene.soft_bodies.size() && i < frame.soft_nodes.size(); ++i) {
    softBody(scene.soft_bodies[i], frame.soft_nodes[i], look.soft_tint);
  }
  if (view.contacts) contacts(frame.contacts, 0.02 * camera.distance);
}

void overlay(const std::string& text, int width, int height) {
  constexpr float kScale = 2.0f;  // stb_easy_font's glyphs are 7 pixels tall
  static char quads[64 * 1024];
  const int count = stb_easy_font_print(5.0f, 5.0f, const_cast<char*>(text.c_str()), nullptr, quads,
                                        sizeof quads);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, width, height, 0, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glScalef(kScale, kScale, 1.0f);
  glDisable(GL_LIGHTING);
  glDisable(GL_DEPTH_TEST);
  glColor3f(0.15f, 0.15f, 0.2f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 16, quads);
  glDrawArrays(GL_QUADS, 0, count * 4);
  glDisableClientState(GL_VERTEX_ARRAY);
  glEnable(GL_DEPTH_TEST);
}

std::vector<std::uint8_t> readPixels(int width, int height) {
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * height * 3);
  glFinish();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  // OpenGL's rows start at the bottom.
  const std::size_t row = static_cast<std::size_t>(width) * 3;
  for (int y = 0; y < height / 2; ++y) {
    std::swap_ranges(rgb.begin() + y * row, rgb.begin() + (y + 1) * row,
                     rgb.begin() + (height - 1 - y) * row);
  }
  return rgb;
}

void readPixelsRgba(int width, int height, std::vector<std::uint8_t>& rgba) {
  rgba.resize(static_cast<std::size_t>(width) * height * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
}

}  // namespace viewer::detail

// The one interface every method implements (DESIGN.md, "Every method
// implements one small core interface"): built from a scene and the method's
// settings, it solves with progress and abort, gives the surface solution
// (the SPEC output of port 0) and the method's own product (port 1: the
// discontinuity mesh with its interpolants, the Shepard field's points, the
// leaf clusters with their vector irradiance). The filter, the command line
// and later the scene-graph pass handle methods once through it.
#ifndef Radiosity_RadiositySolver_h
#define Radiosity_RadiositySolver_h

#include "Radiosity/Common/ProbeEvaluator.h"
#include "Radiosity/Common/Scene.h"
#include "Radiosity/Common/ScenePieces.h"
#include "Radiosity/Common/SolutionMesh.h"
#include "Radiosity/Common/SolverTypes.h"

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace radiosity
{
/// A named array of a product or of the surface: `Components` values per
/// tuple, stored as doubles; `Type` says what the VTK array should be.
struct ProductArray
{
  enum class ValueType
  {
    Double,
    Int,
    IdType,
    UnsignedChar
  };
  std::string Name;
  int Components = 1;
  ValueType Type = ValueType::Double;
  std::vector<double> Values;

  ProductArray() = default;
  ProductArray(std::string name, int components, std::size_t tuples, ValueType type = ValueType::Double)
    : Name(std::move(name))
    , Components(components)
    , Type(type)
    , Values(tuples * static_cast<std::size_t>(components), 0.0)
  {
  }
  std::size_t Tuples() const { return this->Components > 0 ? this->Values.size() / this->Components : 0; }
  double* Tuple(std::size_t i) { return this->Values.data() + i * static_cast<std::size_t>(this->Components); }
  void SetRGB(std::size_t i, const RGB& c)
  {
    double* t = this->Tuple(i);
    t[0] = c.x;
    t[1] = c.y;
    t[2] = c.z;
  }
};

/// A method's own product: points, triangles over them (none: every point
/// is a vertex cell) and named arrays on both. Empty Kind: the method has no
/// product beyond the surface (progressive refinement).
struct SolverProduct
{
  std::string Kind;
  std::vector<Vec3> Points;
  std::vector<Triangle> Triangles;
  std::vector<ProductArray> PointArrays, CellArrays;
  std::vector<std::string> Warnings;
  /// False when the product's computation was aborted part-way.
  bool Complete = true;
};

class RadiositySolver
{
public:
  virtual ~RadiositySolver() = default;
  /// The method's name as the command line spells it ("progressive", ...).
  virtual const char* MethodName() const = 0;
  virtual SolverStatistics Solve(const ProgressCallback& progress) = 0;
  /// The surface solution: the elements with the SPEC fields.
  virtual SolutionMesh Surface() const = 0;
  /// The surface's elements of the input triangles t with keep[t] != 0 (an
  /// MPI rank's own part; SolutionOfTriangles: `pointSource` the index of
  /// each point in Surface()'s points). A method whose output costs
  /// evaluates only those.
  virtual SolutionMesh SurfaceOf(const std::vector<char>& keep, std::vector<std::uint32_t>* pointSource) const
  {
    return SolutionOfTriangles(this->Surface(), keep, pointSource);
  }
  /// Point arrays of the surface beyond the SPEC fields (face cluster: the
  /// irradiance vectors for vtkVectorIrradianceMapper); none by default.
  virtual std::vector<ProductArray> SurfacePointArrays() const { return {}; }
  /**
   * Irradiance at sensors (SPEC: --probes) from the method's own solution
   * representation, the punctual lights' direct light taken exactly at each
   * sensor (ProbeEvaluator::SetExactPunctualLight). By default from the
   * surface (ProbeEvaluator); the hierarchical method evaluates its
   * quadratic interpolants, the meshless one its Shepard field, the face
   * cluster one its vector irradiance bases. `gathered`: how many sensors
   * lay on no surface and were gathered from the solution instead.
   */
  virtual std::vector<RGB> EvaluateProbes(const std::vector<Probe>& probes, std::size_t* gathered = nullptr) const
  {
    const SolutionMesh surface = this->Surface();
    const ProbeEvaluator evaluator(surface, *this->SceneRef);
    std::vector<RGB> values = evaluator.Evaluate(probes);
    if (gathered)
    {
      *gathered = evaluator.GatheredCount();
    }
    return values;
  }
  /// The method's own product (may take time: progress and abort apply).
  virtual SolverProduct Product(const ProgressCallback& progress) const = 0;

  ///@{
  /**
   * Relighting (Lehtinen et al. 2007, section 6.5): after Solve, a method
   * that supports it precomputes its light transfer (false when aborted
   * through `progress`; SceneError when it cannot); then Relight solves for
   * the lighting of `scene` (new emission, lights, sky; the same surfaces,
   * else SceneError naming the difference), which becomes the solver's
   * scene. Meshless relights lights, sky and emission (a precomputed
   * transfer), face cluster lights and sky (kept transfer couplings); the
   * other methods refuse with a SceneError.
   */
  virtual bool SupportsRelighting() const { return false; }
  virtual bool HasRelighting() const { return false; }
  virtual bool PrecomputeRelighting(const ProgressCallback& progress)
  {
    (void)progress;
    throw SceneError(std::string(this->MethodName()) + " radiosity has no relighting (meshless and facecluster have)");
  }
  virtual SolverStatistics Relight(std::shared_ptr<const Scene> scene, const ProgressCallback& progress)
  {
    (void)scene;
    (void)progress;
    throw SceneError(std::string(this->MethodName()) + " radiosity has no relighting (meshless and facecluster have)");
  }
  /// The time a relight may spend adding to its transfer (0: no limit; the
  /// rest waits for the next relights). Ignored by a method without relighting.
  virtual void SetRelightGatherSeconds(double seconds) { (void)seconds; }
  ///@}
  const Scene& GetScene() const { return *this->SceneRef; }
  std::shared_ptr<const Scene> SharedScene() const { return this->SceneRef; }

protected:
  explicit RadiositySolver(std::shared_ptr<const Scene> scene)
    : SceneRef(std::move(scene))
  {
  }
  /// Every method's solver references the scene; the interface keeps it alive.
  std::shared_ptr<const Scene> SceneRef;
};

/// What every method's adapter shares: it owns the method's solver, built on
/// the shared scene, and forwards Solve to it.
template <typename Instance>
class MethodSolver : public RadiositySolver
{
public:
  SolverStatistics Solve(const ProgressCallback& progress) override
  {
    return this->Solver.Solve(progress);
  }
  /// The method's own solver (its statistics, fields, hierarchy).
  const Instance& GetInstance() const { return this->Solver; }

protected:
  /// Builds the method's solver as Instance(scene, args...).
  template <typename... Args>
  explicit MethodSolver(std::shared_ptr<const Scene> scene, Args&&... args)
    : RadiositySolver(std::move(scene))
    , Solver(*this->SceneRef, std::forward<Args>(args)...)
  {
  }
  Instance Solver;
};
} // namespace radiosity

#endif

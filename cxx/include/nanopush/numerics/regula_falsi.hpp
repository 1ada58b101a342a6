// The Illinois variant of regula falsi (Dowell & Jarratt 1971), the event locator of the
// stick-slip law (models/stick_slip.cpp) and of the kinks of a scene's right-hand side
// (scenes/kinks.cpp): each value of g costs a sub-integration, so the bracket shrinks from
// both sides (the stale end's value halved when the same end moves twice) without the
// bookkeeping of Brent's method.
#pragma once

namespace nanopush::roots {

/// Shrinks the bracket [a, b], with g(a) = ga and g(b) = gb of opposite signs, towards the
/// zero of g. Each step tries the secant point c (the midpoint when c is not inside (a, b)),
/// evaluates gc = g(c) and replaces the end whose value has the sign of gc; when the same end
/// moves twice in a row, the other end's value is halved (the Illinois step). Stops after
/// `max_iterations` steps, when `keep_going(a, b)` is false, or when gc == 0 (then a = b = c).
/// After each step `moved(side)` tells what c replaced: -1 the end a, +1 the end b, 0 both
/// (gc == 0), so a caller can keep the states that go with the ends. G is g's value type
/// (double or an extended scalar); the bracket is double.
template <class G, class Eval, class KeepGoing, class Moved>
void illinois(double& a, double& b, G ga, G gb, int max_iterations, KeepGoing&& keep_going, Eval&& g,
              Moved&& moved) {
  int side = 0;
  for (int it = 0; it < max_iterations && keep_going(a, b); ++it) {
    double c = static_cast<double>((a * gb - b * ga) / (gb - ga));
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const G gc = g(c);
    if (gc == 0.0) {
      a = b = c;
      moved(0);
      break;
    }
    if ((gc > 0.0) == (ga > 0.0)) {
      a = c;
      ga = gc;
      moved(-1);
      if (side == -1) gb *= 0.5;
      side = -1;
    } else {
      b = c;
      gb = gc;
      moved(1);
      if (side == 1) ga *= 0.5;
      side = 1;
    }
  }
}

}  // namespace nanopush::roots

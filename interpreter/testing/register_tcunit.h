// Binds the TcUnit / CfUnit API into the checker: TEST, TEST_ORDERED,
// TEST_FINISHED, TEST_FINISHED_NAMED, IS_TEST_FINISHED, RUN,
// RUN_IN_SEQUENCE, TCUNIT_ADSLOGSTR and every Assert* function. They are
// built-ins (a user POU of the same name shadows them) because an assertion
// must know where it is written (the FILE:LINE of a FAIL line) and compare
// values of any type. The suite base class FB_TestSuite and the
// WRITE_PROTECTED_* helpers are ST, in stdlib/st/tcunit.st.
#pragma once

namespace strun::sema { class Checker; }

namespace strun::testing {

class TestRegistry;

void registerTcUnit(sema::Checker& checker, TestRegistry& registry);

}  // namespace strun::testing

#pragma once
// A fixture of check-ui-class-size.py: a class one public member function over the limit (31),
// with the shapes the reader must not count (constructor, destructor, deleted copy, fields, a
// std::function field, a nested struct's methods, private methods).
#include <functional>

namespace fixture {

class Big {
  public:
    Big();
    ~Big();
    Big(const Big&) = delete;
    void method0(int value);
    void method1(int value);
    void method2(int value);
    void method3(int value);
    void method4(int value);
    void method5(int value);
    void method6(int value);
    void method7(int value);
    void method8(int value);
    void method9(int value);
    void method10(int value);
    void method11(int value);
    void method12(int value);
    void method13(int value);
    void method14(int value);
    void method15(int value);
    void method16(int value);
    void method17(int value);
    void method18(int value);
    void method19(int value);
    void method20(int value);
    void method21(int value);
    void method22(int value);
    void method23(int value);
    void method24(int value);
    void method25(int value);
    void method26(int value);
    void method27(int value);
    void method28(int value);
    void method29(int value);
    void method30(int value);
    std::function<void()> callback;
    int field = 0;
    struct Nested {
        void notCounted();
    };

  private:
    void hidden();
};

} // namespace fixture

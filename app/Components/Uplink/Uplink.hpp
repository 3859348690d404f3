// SPDX-License-Identifier: Apache-2.0
// ======================================================================
// \title  Uplink.hpp
// \brief  Scripted command uplink into the command dispatcher
// ======================================================================
#ifndef KIT_UPLINK_HPP
#define KIT_UPLINK_HPP

#include "app/Components/Uplink/UplinkComponentAc.hpp"

namespace Kit {

class Uplink final : public UplinkComponentBase {
  public:
    static constexpr FwSizeType FRAME_MAX = 16;   //!< bytes in one frame
    static constexpr FwSizeType SCRIPT_MAX = 16;  //!< frames in one script

    //! What happened to a frame
    struct FrameResult {
        bool sent;
        bool answered;
        FwOpcodeType opcode;
        Fw::CmdResponse response;
    };

    //! One uplinked frame: raw bytes, sent at a given 10 Hz cycle counted from
    //! play(), the answer the scenario expects, and what happened to it
    struct Frame {
        U32 cycle;
        U8 size;
        U8 bytes[FRAME_MAX];
        Fw::CmdResponse expected;
        FrameResult result;

        //! Answered as expected
        bool asExpected() const { return result.sent && result.answered && result.response == expected; }
    };

    //! A well-formed command frame: descriptor, opcode, argument bytes
    static Frame commandFrame(U32 cycle, FwOpcodeType opcode, const U8* args, FwSizeType argSize);

    //! Any bytes at all, as a noisy link delivers them; the dispatcher must
    //! reject them with `expected`
    static Frame rawFrame(U32 cycle, const U8* bytes, FwSizeType size, Fw::CmdResponse expected);

    explicit Uplink(const char* const compName);
    ~Uplink();

    //! Send these frames, each `cycle` 10 Hz cycles from now; the array (which
    //! receives the results) must outlive the play. Replaces the frames of an
    //! earlier play: call it between run segments, when nothing is in flight.
    void play(Frame* frames, FwSizeType count);

  private:
    void schedIn_handler(FwIndexType portNum, U32 context) override;
    void cmdResponseIn_handler(FwIndexType portNum,
                               FwOpcodeType opCode,
                               U32 cmdSeq,
                               const Fw::CmdResponse& response) override;

    Frame* m_frames;
    FwSizeType m_count;
    U32 m_cycle;      //!< 10 Hz cycles since boot
    U32 m_playStart;  //!< m_cycle when play() was called
    U32 m_sent;
    U32 m_rejected;
};

}  // namespace Kit

#endif
